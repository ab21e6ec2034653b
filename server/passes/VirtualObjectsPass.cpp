#include "passes/VirtualObjectsPass.h"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <limits>

#include <glm/gtx/component_wise.hpp>

#include "math/Transform.h"
#include "passes/ReflectionResources.h"
#include "passes/ShadingUniforms.h"

namespace specula::passes {

namespace {
// Virtual vertices lie a whole path (eye → mirror → object) away: push the far plane out.
constexpr float kVirtualFarScale = 3.0f;
constexpr int kCastTile = 8;                // pixels per side of a ray-cast tile (ray-cast-tiles.comp)
constexpr std::size_t kCastTileGroup = 64;  // tiles per work group (ray-cast-tiles.comp)
// Tile-list entries and nearest-hit pixels of one frame (16 and 32 MiB): parts past either cast
// every object over all their pixels.
constexpr std::size_t kCastTileListBudget = std::size_t{4} << 20;
constexpr std::size_t kNearestHitBudget = std::size_t{8} << 20;
}  // namespace

Result<std::unique_ptr<VirtualObjectsPass>> VirtualObjectsPass::create(const gl::GlApi& gl) {
  auto objects =
      gl::ShaderProgram::build(gl, {"virtual-objects/virtual-objects.vert", "virtual-objects/virtual-objects.geom",
                                    "virtual-objects/virtual-objects.frag"});
  if (!objects) return Error{objects.error()};
  auto tessellated = gl::ShaderProgram::build(
      gl, {"virtual-objects/virtual-objects-tessellated.vert", "virtual-objects/virtual-objects.frag"});
  if (!tessellated) return Error{tessellated.error()};
  auto region = gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "virtual-objects/mirror-region.frag"});
  if (!region) return Error{region.error()};
  auto rayCast = gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "virtual-objects/ray-cast.frag"});
  if (!rayCast) return Error{rayCast.error()};
  auto rayCastTiles =
      gl::ShaderProgram::build(gl, {"virtual-objects/ray-cast-tile.vert", "virtual-objects/ray-cast.frag"});
  if (!rayCastTiles) return Error{rayCastTiles.error()};
  auto classifyTiles = gl::ShaderProgram::build(gl, {"virtual-objects/ray-cast-tiles.comp"});
  if (!classifyTiles) return Error{classifyTiles.error()};
  auto findUncovered =
      gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "virtual-objects/uncovered-pixels.frag"});
  if (!findUncovered) return Error{findUncovered.error()};
  auto uncoveredPixel =
      gl::ShaderProgram::build(gl, {"virtual-objects/uncovered-pixel.vert", "virtual-objects/ray-cast.frag"});
  if (!uncoveredPixel) return Error{uncoveredPixel.error()};
  auto reflectedEnvironment =
      gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "virtual-objects/reflected-environment.frag"});
  if (!reflectedEnvironment) return Error{reflectedEnvironment.error()};
  auto composite =
      gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "virtual-objects/reflection-composite.frag"});
  if (!composite) return Error{composite.error()};
  return std::unique_ptr<VirtualObjectsPass>(new VirtualObjectsPass(
      gl, std::move(objects.value()), std::move(tessellated.value()), std::move(region.value()),
      std::move(rayCast.value()), std::move(rayCastTiles.value()), std::move(classifyTiles.value()),
      std::move(findUncovered.value()), std::move(uncoveredPixel.value()), std::move(reflectedEnvironment.value()),
      std::move(composite.value())));
}

void VirtualObjectsPass::drawMesh(const FrameContext& frame, const ReflectionSlotRange& range,
                                  std::optional<GLintptr> indirect) const {
  frame.setReflectedObject(objects_, range);
  setMaterial(objects_, frame.scene.materials[frame.scene.objects[range.object].material], frame.textures);
  const std::size_t mesh = frame.scene.objects[range.object].mesh;
  if (indirect) frame.meshes.drawIndirect(mesh, *indirect);
  else frame.meshes.draw(mesh);
}

void VirtualObjectsPass::drawObjects(const FrameContext& frame, const PlannedMirror& mirror) const {
  const gl::GlApi& gl = frame.gl;
  if (!frame.plan.tessellate) {
    objects_.use();
    for (const ReflectionSlotRange* range : mirror.reflected) drawMesh(frame, *range);
    return;
  }
  // Each of the part's runs as the tessellation's GPU records say: its mesh (when nothing of it
  // split, or it found no room) and each round's finished triangles, all by indirect commands.
  const TessellationBuffers& tessellation = frame.reflections.tessellation();
  const std::vector<TessellatedRun>& runs = tessellation.frameRuns();
  gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, tessellation.draws());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, VIRTUAL_OBJECTS_TRIANGLES_BINDING, tessellation.finished());
  const auto rounds = static_cast<GLsizei>(frame.settings.tessellation.maxLevel + 1);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].mirror != mirror.slots) continue;  // another mirror, or another part of this one
    const std::size_t draws = i * sizeof(gpu::RunDraws);
    objects_.use();
    drawMesh(frame, *runs[i].object, static_cast<GLintptr>(draws + offsetof(gpu::RunDraws, mesh)));
    if (!runs[i].rounds) continue;
    tessellated_.use();
    gl.BindVertexArray(emptyVertexArray_.id());
    setMaterial(tessellated_, frame.scene.materials[frame.scene.objects[runs[i].object->object].material],
                frame.textures);
    gl.MultiDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(draws + offsetof(gpu::RunDraws, rounds)),
                               rounds, 0);
  }
  gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

void VirtualObjectsPass::queueStatistics(gl::GpuReadback& readback) {
  std::size_t commands = 0;
  for (const CastPart& part : castParts_) commands += part.tiled ? part.objects.size() : 0;
  castCommands_ = commands;
  uncoveredHandle_ =
      readback.copy(uncoveredCounts_.id(), std::max<std::size_t>(plannedParts_, 1) * sizeof(std::uint32_t));
  if (commands > 0) castHandle_ = readback.copy(castDraws_.id(), commands * sizeof(DrawCommand));
}

std::vector<VirtualObjectsPass::PartStatistics> VirtualObjectsPass::readStatistics(
    const gl::GpuReadback& readback) const {
  std::vector<PartStatistics> parts(plannedParts_);
  const std::vector<std::uint32_t> uncovered = readback.read<std::uint32_t>(uncoveredHandle_, plannedParts_);
  const std::vector<DrawCommand> draws = readback.read<DrawCommand>(castHandle_, castCommands_);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    parts[i].uncoveredRayCast = uncovered[i];
    if (i >= castParts_.size()) continue;
    const CastPart& part = castParts_[i];
    CastTileCount& tiles = parts[i].castTiles;
    tiles.possible = part.objects.size() * part.tileCapacity;
    if (!part.tiled) {
      tiles.listed = tiles.possible;
      continue;
    }
    for (std::size_t k = 0; k < part.objects.size(); ++k) tiles.listed += draws[part.firstObject + k].instances;
  }
  return parts;
}

void VirtualObjectsPass::rayCastUncovered(const FrameContext& frame, const PlannedMirror& planned,
                                          std::size_t partIndex) {
  const gl::GlApi& gl = frame.gl;
  const PixelRect pixels = framePixels(frame.reflections.coveredFramePixels(planned.slots->layer), frame);
  if (pixels.size().x <= 0 || pixels.size().y <= 0 || planned.reflected.empty()) return;
  // Room for every pixel of the frame after the indirect draw command: kept while the size stays.
  const GLsizeiptr bytes =
      static_cast<GLsizeiptr>(sizeof(DrawCommand) + sizeof(std::uint32_t) * reflectionSize_.x * reflectionSize_.y);
  gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, uncovered_.id());
  if (bytes != uncoveredBytes_) {
    gl.BufferData(GL_DRAW_INDIRECT_BUFFER, bytes, nullptr, GL_DYNAMIC_COPY);
    uncoveredBytes_ = bytes;
  }
  const DrawCommand empty{0, 1, 0, 0};
  gl.BufferSubData(GL_DRAW_INDIRECT_BUFFER, 0, sizeof(empty), &empty);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, uncovered_.id());
  std::vector<glm::vec4> boxes;
  boxes.reserve(2 * planned.reflected.size());
  for (const ReflectionSlotRange* range : planned.reflected) {
    boxes.emplace_back(frame.worldBounds[range->object].low, 0.0f);
    boxes.emplace_back(frame.worldBounds[range->object].high, 0.0f);
  }
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, reflectedBoxes_.id());
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(boxes.size() * sizeof(glm::vec4)), boxes.data(),
                GL_STREAM_DRAW);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, reflectedBoxes_.id());

  // Listed by a draw over the part's stencil into a framebuffer without colour, so that the
  // reflection buffer can be read.
  gl.BindFramebuffer(GL_FRAMEBUFFER, stencilOnly_.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                          frame.target.depthStencilTexture(), 0);
  const GLenum noColour = GL_NONE;
  gl.DrawBuffers(1, &noColour);
  gl.DepthMask(GL_FALSE);
  gl.DepthFunc(GL_ALWAYS);
  useReadingReflection(findUncovered_, frame);
  findUncovered_.set("layer", planned.slots->layer);
  findUncovered_.set("boxCount", static_cast<int>(planned.reflected.size()));
  findUncovered_.set("environmentPart", planned.method == PartMethod::EnvironmentMap ? 1 : 0);
  findUncovered_.set("environmentReach", planned.environmentReach);
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, uncoveredCounts_.id());
  gl.CopyBufferSubData(GL_DRAW_INDIRECT_BUFFER, GL_COPY_WRITE_BUFFER, 0,
                       static_cast<GLintptr>(partIndex * sizeof(std::uint32_t)), sizeof(std::uint32_t));
  gl.DepthMask(GL_TRUE);
  gl.DepthFunc(GL_LESS);

  uncoveredPixel_.use();
  uncoveredPixel_.set("frameSize", glm::vec2(frame.target.width(), frame.target.height()));
  for (const ReflectionSlotRange* range : planned.reflected) {
    prepareRayCast(frame, uncoveredPixel_, *planned.slots, range->object);
    gl.DrawArraysIndirect(GL_POINTS, nullptr);
  }
  gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

void VirtualObjectsPass::useReadingReflection(const gl::ShaderProgram& program, const FrameContext& frame) const {
  const gl::GlApi& gl = frame.gl;
  program.use();
  gl.ActiveTexture(GL_TEXTURE2);
  gl.BindTexture(GL_TEXTURE_2D, reflection_.id());
  gl.ActiveTexture(GL_TEXTURE0);
  program.set("reflection", 2);
  setGBufferSamplers(program);  // the G-buffer textures are bound by execute()
  setGBufferPixelMapping(program, frame.reflections);
  program.set("eyePosition", frame.pose.camera.eye);
  program.set("errorBudget", frame.settings.errorBudgetPixels);
}

void VirtualObjectsPass::rayCast(const FrameContext& frame, const MirrorSlots& mirror, std::size_t objectIndex) const {
  prepareRayCast(frame, rayCast_, mirror, objectIndex);
  frame.gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

void VirtualObjectsPass::setCastRay(const FrameContext& frame, const gl::ShaderProgram& program,
                                    const MirrorSlots& mirror) {
  ReflectionResources& resources = frame.reflections;
  program.use();
  setGBufferSamplers(program);  // the G-buffer textures are bound by execute()
  setGBufferPixelMapping(program, resources);
  program.set("layer", mirror.layer);
  program.set("eyePosition", frame.pose.camera.eye);
  // The G-buffer point's own error: half a texel where pixel centres fall between texels, and the
  // rounding of half floats at the mirror's largest coordinate.
  const float pixelAngle = frame.view.pixelAngle(frame.target.height());
  const float texelsPerPixel = resources.texelsPerPixel();
  const bool texelPerPixel =
      std::abs(texelsPerPixel - 1.0f) < 1e-3f;  // pixel centres on texel centres: no interpolation
  program.set("liftPerMetre", texelPerPixel ? 0.0f : 0.5f * pixelAngle / texelsPerPixel);
  const math::Bounds& mirrorBounds = frame.worldBounds[mirror.mirrorObject];
  const float largestCoordinate = glm::compMax(glm::max(glm::abs(mirrorBounds.low), glm::abs(mirrorBounds.high)));
  program.set("lift", frame.plan.gbufferPrecision == GBufferPrecision::Float16 ? largestCoordinate / 2048.0f : 0.0f);
}

void VirtualObjectsPass::prepareRayCast(const FrameContext& frame, const gl::ShaderProgram& program,
                                        const MirrorSlots& mirror, std::size_t objectIndex) const {
  const gl::GlApi& gl = frame.gl;
  const scene::SceneObject& object = frame.scene.objects[objectIndex];
  const ReflectionResources::MeshBvh& bvh = frame.reflections.meshBvh(object.mesh);
  const glm::mat4& objectToWorld = frame.pose.objectToWorld[objectIndex];
  setCastRay(frame, program, mirror);
  program.set("firstHit", -1);  // no nearest-hit bound unless setNearestHits follows
  program.set("objectToWorld", objectToWorld);
  program.set("worldToObject", glm::inverse(objectToWorld));
  program.set("normalToWorld", math::normalMatrix(objectToWorld));
  program.set("worldToClip", frame.view.worldToClip(glm::vec2(1.0f), kVirtualFarScale));
  // Only a mirror that shows itself starts its rays on the object cast against; any other object is
  // hit from distance 0, so one the mirror stands on (a cylinder on the floor) meets it at the contact.
  program.set("minDistance", objectIndex == mirror.mirrorObject ? bvh.minDistance : 0.0f);
  program.set("reflectivity", frame.scene.materials[frame.scene.objects[mirror.mirrorObject].material].reflectivity);
  setSceneLighting(program, frame.scene);
  setMaterial(program, frame.scene.materials[object.material], frame.textures);
  setRayCone(program, frame);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, bvh.nodes.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, bvh.triangles.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, frame.meshes.vertexBuffer(object.mesh));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, frame.meshes.indexBuffer(object.mesh));
  gl.BindVertexArray(emptyVertexArray_.id());
}

void VirtualObjectsPass::classifyCastTiles(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  castParts_.assign(frame.plan.mirrors.size(), CastPart{});
  std::vector<glm::vec4> spheres;
  std::size_t entries = 0, pixelCount = 0;
  for (std::size_t partIndex = 0; partIndex < frame.plan.mirrors.size(); ++partIndex) {
    const PlannedMirror& planned = frame.plan.mirrors[partIndex];
    if (planned.method != PartMethod::RayCast) continue;
    const MirrorSlots& mirror = *planned.slots;
    CastPart& part = castParts_[partIndex];
    if (mirror.seesItself) part.objects.push_back(mirror.mirrorObject);
    for (const ReflectionSlotRange* range : planned.reflected) part.objects.push_back(range->object);
    // Nearest to the mirror first: their hits then bound the later objects' traversals (nearestHits_).
    const glm::vec3 mirrorCentre = frame.worldBounds[mirror.mirrorObject].center();
    const auto nearestReach = [&](std::size_t object) {
      const math::Bounds& bounds = frame.worldBounds[object];
      return glm::length(bounds.center() - mirrorCentre) - 0.5f * glm::length(bounds.high - bounds.low);
    };
    std::stable_sort(part.objects.begin(), part.objects.end(),
                     [&](std::size_t a, std::size_t b) { return nearestReach(a) < nearestReach(b); });
    const PixelRect pixels = framePixels(frame.reflections.coveredFramePixels(mirror.layer), frame);
    part.firstTile = pixels.low / kCastTile;
    part.tileExtent = (pixels.high + kCastTile - 1) / kCastTile - part.firstTile;
    part.tileCapacity = static_cast<std::size_t>(part.tileExtent.x) * static_cast<std::size_t>(part.tileExtent.y);
    const std::size_t needed = part.objects.size() * part.tileCapacity;
    const std::size_t partPixels =
        static_cast<std::size_t>(pixels.size().x) * static_cast<std::size_t>(pixels.size().y);
    // A part whose lists or nearest hits would pass their budgets casts every object over all its
    // pixels instead. So does a part of one object: on llvmpipe classifying its tiles costs what
    // the tiles it leaves out would (checker-sphere and quad, one object on a third to half of it).
    part.tiled = frame.settings.castTiles && part.objects.size() >= 2 && part.tileCapacity > 0 &&
                 entries + needed <= kCastTileListBudget && pixelCount + partPixels <= kNearestHitBudget;
    if (!part.tiled) continue;
    part.firstObject = spheres.size();
    part.firstEntry = entries;
    entries += needed;
    part.pixelLow = pixels.low;
    part.pixelHigh = pixels.high;
    part.firstHit = pixelCount;
    pixelCount += partPixels;
    for (const std::size_t object : part.objects) {
      const math::Bounds& bounds = frame.worldBounds[object];
      spheres.emplace_back(bounds.center(), 0.5f * glm::length(bounds.high - bounds.low));
    }
  }
  if (spheres.empty()) return;
  castTileLists_.reserve(gl, static_cast<GLsizeiptr>(entries * sizeof(std::uint32_t)));
  nearestHits_.reserve(gl, static_cast<GLsizeiptr>(pixelCount * sizeof(std::uint32_t)));
  const std::vector<DrawCommand> noTilesYet(spheres.size(), DrawCommand{6, 0, 0, 0});
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, castObjects_.id());
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(spheres.size() * sizeof(glm::vec4)), spheres.data(),
                GL_STREAM_DRAW);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, castDraws_.id());
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(noTilesYet.size() * sizeof(DrawCommand)),
                noTilesYet.data(), GL_STREAM_DRAW);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, castObjects_.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, castDraws_.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, castTileLists_.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 13, nearestHits_.id());
  // Every part classified back to back before any cast is drawn: llvmpipe runs a dispatch only
  // after the draws queued before it, so one per part between draws would serialise the frame.
  for (std::size_t partIndex = 0; partIndex < castParts_.size(); ++partIndex) {
    const CastPart& part = castParts_[partIndex];
    if (!part.tiled) continue;
    setCastRay(frame, classifyTiles_, *frame.plan.mirrors[partIndex].slots);
    setNearestHits(classifyTiles_, part);
    classifyTiles_.set("firstTile", part.firstTile);
    classifyTiles_.set("tileExtent", part.tileExtent);
    classifyTiles_.set("firstObject", static_cast<int>(part.firstObject));
    classifyTiles_.set("objectCount", static_cast<int>(part.objects.size()));
    classifyTiles_.set("firstEntry", static_cast<unsigned>(part.firstEntry));
    classifyTiles_.set("tileCapacity", static_cast<unsigned>(part.tileCapacity));
    gl.DispatchCompute(static_cast<GLuint>((part.tileCapacity + kCastTileGroup - 1) / kCastTileGroup), 1, 1);
  }
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void VirtualObjectsPass::setNearestHits(const gl::ShaderProgram& program, const CastPart& part) {
  program.set("hitPixelLow", part.pixelLow);
  program.set("hitPixelHigh", part.pixelHigh);
  program.set("firstHit", static_cast<int>(part.firstHit));
}

void VirtualObjectsPass::rayCastPart(const FrameContext& frame, std::size_t partIndex) const {
  const gl::GlApi& gl = frame.gl;
  const CastPart& part = castParts_[partIndex];
  const MirrorSlots& mirror = *frame.plan.mirrors[partIndex].slots;
  if (!part.tiled) {
    for (const std::size_t object : part.objects) rayCast(frame, mirror, object);
    return;
  }
  gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, castDraws_.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, castTileLists_.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 13, nearestHits_.id());
  for (std::size_t k = 0; k < part.objects.size(); ++k) {
    prepareRayCast(frame, rayCastTiles_, mirror, part.objects[k]);
    setNearestHits(rayCastTiles_, part);
    rayCastTiles_.set("listBase", static_cast<unsigned>(part.firstEntry + k * part.tileCapacity));
    rayCastTiles_.set("frameSize", glm::vec2(frame.target.width(), frame.target.height()));
    gl.DrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>((part.firstObject + k) * sizeof(DrawCommand)));
  }
  gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

VirtualObjectsPass::PixelRect VirtualObjectsPass::framePixels(const glm::vec4& rect, const FrameContext& frame) {
  const glm::ivec2 size(frame.target.width(), frame.target.height());
  const glm::ivec2 low = glm::clamp(glm::ivec2(glm::floor(glm::vec2(rect.x, rect.y))), glm::ivec2(0), size);
  return {low, glm::clamp(glm::ivec2(glm::ceil(glm::vec2(rect.z, rect.w))), low, size)};
}

void VirtualObjectsPass::drawReflectedEnvironment(const FrameContext& frame, const MirrorSlots& mirror,
                                                  float reflectivity) const {
  const gl::GlApi& gl = frame.gl;
  reflectedEnvironment_.use();
  reflectedEnvironment_.set("layer", mirror.layer);
  reflectedEnvironment_.set("reflectivity", reflectivity);
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.DepthMask(GL_FALSE);  // the mirror's depth stays at the far plane for its virtual objects
  gl.DepthFunc(GL_ALWAYS);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

void VirtualObjectsPass::resetMirrorDepth(const FrameContext& frame) const {
  // Virtual objects lie behind the mirror's surface: its pixels start at the far plane.
  const gl::GlApi& gl = frame.gl;
  region_.use();
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl.Disable(GL_BLEND);
  gl.DepthMask(GL_TRUE);
  gl.DepthFunc(GL_ALWAYS);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

void VirtualObjectsPass::bindReflectionBuffer(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  const glm::ivec2 size(frame.target.width(), frame.target.height());
  if (size != reflectionSize_) {
    reflection_ = gl::GlTexture(gl);  // immutable storage: replace it
    gl.BindTexture(GL_TEXTURE_2D, reflection_.id());
    gl.TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA16F, size.x, size.y);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    reflectionSize_ = size;
  }
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, reflection_.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                          frame.target.depthStencilTexture(), 0);
  gl.Viewport(0, 0, size.x, size.y);
}

void VirtualObjectsPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  bindReflectionBuffer(frame);
  plannedParts_ = frame.plan.mirrors.size();
  const std::vector<std::uint32_t> noneYet(plannedParts_, 0);
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, uncoveredCounts_.id());
  gl.BufferData(GL_COPY_WRITE_BUFFER,
                static_cast<GLsizeiptr>(std::max<std::size_t>(1, plannedParts_) * sizeof(std::uint32_t)),
                noneYet.empty() ? nullptr : noneYet.data(), GL_DYNAMIC_READ);
  gl.Disable(GL_FRAMEBUFFER_SRGB);  // linear until the composite writes the frame
  gl.Disable(GL_BLEND);
  gl.Disable(GL_SCISSOR_TEST);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const GLfloat nothing[] = {0.0f, 0.0f, 0.0f, 0.0f};
  gl.ClearBufferfv(GL_COLOR, 0, nothing);
  gl.Enable(GL_STENCIL_TEST);
  gl.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gl.StencilMask(0);
  gl.Enable(GL_DEPTH_TEST);
  gl.Disable(GL_CULL_FACE);  // reflection flips winding; open meshes are two-sided anyway
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, frame.reflections.reflectedVertices());

  bindGBufferTextures(gl, frame.reflections);
  // A black background adds nothing to the reflection buffer, cleared to black: no draw per part for it.
  const bool reflectsEnvironment =
      frame.scene.environment.kind != scene::EnvironmentKind::Colour || frame.scene.background != glm::vec3(0.0f);
  reflectedEnvironment_.use();
  setGBufferSamplers(reflectedEnvironment_);
  setGBufferPixelMapping(reflectedEnvironment_, frame.reflections);
  reflectedEnvironment_.set("eyePosition", frame.pose.camera.eye);
  setEnvironment(reflectedEnvironment_, frame.scene, frame.textures);
  classifyCastTiles(frame);
  for (const gl::ShaderProgram* objects : {&objects_, &tessellated_}) {
    objects->use();
    objects->set("worldToClip", frame.view.worldToClip(glm::vec2(1.0f), kVirtualFarScale));
    setGBufferSamplers(*objects);
    objects->set("eyePosition", frame.pose.camera.eye);
    objects->set("frameSize", glm::vec2(frame.target.width(), frame.target.height()));
    objects->set("drawAsPlaced", frame.settings.virtualPixels == VirtualPixels::AsPlaced ? 1 : 0);
    setRayCone(*objects, frame);
    setGBufferPixelMapping(*objects, frame.reflections);
    setSceneLighting(*objects, frame.scene);
  }

  // Every draw below touches one mirror's pixels only: scissored to its parts' screen rectangle, a
  // frame of many small mirrors does not test the whole frame's stencil once per mirror.
  gl.Enable(GL_SCISSOR_TEST);
  const auto scissorToMirror = [&](std::size_t mirrorObject) {
    glm::vec4 rect(std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                   std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest());
    for (const PlannedMirror& part : frame.plan.mirrors) {
      if (part.slots->mirrorObject != mirrorObject) continue;
      const glm::vec4 covered = frame.reflections.coveredFramePixels(part.slots->layer);
      rect = glm::vec4(glm::min(glm::vec2(rect), glm::vec2(covered)),
                       glm::max(glm::vec2(rect.z, rect.w), glm::vec2(covered.z, covered.w)));
    }
    const PixelRect pixels = framePixels(rect, frame);
    gl.Scissor(pixels.low.x, pixels.low.y, pixels.size().x, pixels.size().y);
  };

  // Per mirror: its depth reset to the far plane, then each part's self-reflection and virtual
  // objects; every fragment is an exact hit at its exact depth, so the nearest wins in one pass.
  for (std::size_t partIndex = 0; partIndex < frame.plan.mirrors.size(); ++partIndex) {
    const PlannedMirror& planned = frame.plan.mirrors[partIndex];
    const MirrorSlots* mirror = planned.slots;
    gl.StencilFunc(GL_EQUAL, mirror->stencil, 0xFF);
    if (mirror->part == 0) {
      scissorToMirror(mirror->mirrorObject);
      resetMirrorDepth(frame);
    }
    const float reflectivity = frame.scene.materials[frame.scene.objects[mirror->mirrorObject].material].reflectivity;
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (reflectsEnvironment) drawReflectedEnvironment(frame, *mirror, reflectivity);
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(GL_LESS);
    setForBoth("layer", mirror->layer);
    setForBoth("mirrorRect", frame.reflections.coveredFramePixels(mirror->layer));
    setForBoth("everyCornerReflected", mirror->kind == scene::SurfaceKind::Convex ? 0 : 1);
    setForBoth("reflectivity", reflectivity);
    switch (planned.method) {
      case PartMethod::OwnColour:  // the composite adds the environment it reflects, drawn above
        break;
      case PartMethod::RayCast: rayCastPart(frame, partIndex); break;
      case PartMethod::VirtualObjects:
        if (mirror->seesItself) rayCast(frame, *mirror, mirror->mirrorObject);
        drawObjects(frame, planned);
        if (frame.settings.rayCastUncovered) rayCastUncovered(frame, planned, partIndex);
        break;
      case PartMethod::EnvironmentMap:  // the pixels the cube map cannot serve within the budget
        rayCastUncovered(frame, planned, partIndex);
        break;
    }
  }

  // Each mirror's reflection (or its reflected background) added over its surface in the frame.
  frame.target.bind();
  gl.Enable(GL_FRAMEBUFFER_SRGB);
  gl.Disable(GL_DEPTH_TEST);
  gl.Enable(GL_BLEND);
  gl.BlendFunc(GL_ONE, GL_ONE);
  useReadingReflection(composite_, frame);
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.Enable(GL_SCISSOR_TEST);
  for (const PlannedMirror& planned : frame.plan.mirrors) {
    const MirrorSlots* mirror = planned.slots;
    if (mirror->part != 0) continue;  // once per mirror
    gl.StencilFunc(GL_EQUAL, mirror->stencil, 0xFF);
    scissorToMirror(mirror->mirrorObject);
    // The environment map is chosen for one-part mirrors only: part 0 is the mirror.
    const bool environment = planned.method == PartMethod::EnvironmentMap;
    composite_.set("environmentLayer", environment ? mirror->layer : -1);
    composite_.set("environmentReach", planned.environmentReach);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
  }
  gl.Disable(GL_SCISSOR_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_STENCIL_TEST);
  gl.StencilMask(0xFF);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthMask(GL_TRUE);
  gl.DepthFunc(GL_LESS);
}

}  // namespace specula::passes
