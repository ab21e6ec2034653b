#include "passes/ReflectionResources.h"

#include <algorithm>
#include <string>

#include "math/Bounds.h"
#include "math/TriangleBvh.h"

namespace specula::passes {

TexelRect TexelRect::united(const TexelRect& other) const {
  if (empty()) return other;
  if (other.empty()) return *this;
  return {glm::min(low, other.low), glm::max(high, other.high)};
}

namespace {

void allocateSlots(const gl::GlApi& gl, const gl::GlBuffer& buffer, std::uint32_t slots) {
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
  gl.BufferData(GL_SHADER_STORAGE_BUFFER,
                static_cast<GLsizeiptr>(std::max<std::size_t>(slots, 1) * sizeof(ReflectedVertex)), nullptr,
                GL_DYNAMIC_COPY);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

template <class T>
void upload(const gl::GlApi& gl, const gl::GlBuffer& buffer, const std::vector<T>& data) {
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(data.size(), 1) * sizeof(T)),
                data.empty() ? nullptr : data.data(), GL_STATIC_DRAW);
}

// How many of a parametric mesh's grid deviations a ray cast from its exact surface skips of its own
// grid: utah-teapot at 320x240 had 418 pixels off the ray tracer with none skipped (speckles of its
// own colour where its lid meets the knob), 69 skipping one deviation, 60 skipping four.
constexpr float kGridDeviationsSkipped = 4.0f;

}  // namespace

ReflectionResources::ReflectionResources(const gl::GlApi& gl, const scene::Scene& scene, const ReflectionSlots& slots,
                                         const GpuMeshes& meshes, const GpuDeformation& deformation)
    : gl_(&gl),
      scene_(scene),
      meshes_(meshes),
      deformation_(deformation),
      slots_(slots),
      position_(gl),
      normal_(gl),
      depth_(gl),
      framebuffer_(gl),
      reflected_(gl),
      statistics_(gl),
      tessellation_(gl) {
  allocateSlots(gl, reflected_, slots.slotCount);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, statistics_.id());
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, sizeof(SearchStatistics), nullptr, GL_DYNAMIC_READ);
  for (const auto& [mirrorObject, parts] : slots.parts) {
    if (parts.triangleParts.empty()) continue;
    std::vector<std::uint8_t> packed(parts.triangleParts);
    packed.resize((packed.size() + 3) / 4 * 4, 0);  // whole uints
    upload(gl, triangleParts_.emplace(mirrorObject, gl::GlBuffer(gl)).first->second, packed);
  }
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  for (const MirrorSlots& mirror : slots.mirrors) {
    const scene::MirrorInfo& info = *scene.objects[mirror.mirrorObject].mirror;
    const std::size_t searched = info.closedTwinMesh ? *info.closedTwinMesh : scene.objects[mirror.mirrorObject].mesh;
    parametricMirror_ = parametricMirror_ || !scene.meshes[searched].patches.empty();
  }
  resetCoherence();
  covered_.resize(slots.mirrors.size());
  changed_.resize(slots.mirrors.size());
}

const ReflectionResources::MeshBvh& ReflectionResources::meshBvh(std::uint32_t mesh) {
  if (const auto built = meshBvhs_.find(mesh); built != meshBvhs_.end()) {
    if (deformation_.deforms(mesh)) deformation_.refit(built->second, mesh, meshes_);
    return built->second;
  }
  const scene::Mesh& source = scene_.meshes[mesh];
  std::vector<glm::vec3> positions;
  positions.reserve(source.vertices.size());
  math::Bounds bounds;
  for (const scene::Vertex& v : source.vertices) {
    positions.push_back(v.position);
    bounds.add(v.position);
  }
  const math::TriangleBvh bvh = math::TriangleBvh::build(positions, source.indices);
  MeshBvh& buffers =
      meshBvhs_.emplace(mesh, MeshBvh{gl::GlBuffer(*gl_), gl::GlBuffer(*gl_), 0.0f, {}, {}, 0}).first->second;
  upload(*gl_, buffers.nodes, bvh.nodes());
  upload(*gl_, buffers.triangles, bvh.triangles());
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  // Float rounding of the start point, well below any feature of the mesh; for a parametric mesh, a
  // ray starts on the exact surface and may meet the grid's chords a few deviations along, grazing.
  buffers.minDistance = std::max(1e-4f * std::max(bounds.radius(), 1e-30f),
                                 kGridDeviationsSkipped * static_cast<float>(source.gridDeviation));
  if (!deformation_.deforms(mesh) || bvh.nodes().empty()) return buffers;
  // Built over the rest shape: refitted level by level to the shape the mesh has now, and every frame after.
  std::vector<std::uint32_t> depth(bvh.nodes().size(), 0);
  std::vector<std::vector<std::uint32_t>> levels;
  for (std::uint32_t n = 0; n < bvh.nodes().size(); ++n) {  // children come after their parent
    if (levels.size() <= depth[n]) levels.resize(depth[n] + 1);
    levels[depth[n]].push_back(n);
    const math::TriangleBvh::Node& node = bvh.nodes()[n];
    if (node.count == 0) depth[node.first] = depth[node.first + 1] = depth[n] + 1;
  }
  std::vector<std::uint32_t> order;
  for (auto level = levels.rbegin(); level != levels.rend(); ++level) {
    buffers.levels.push_back({static_cast<std::uint32_t>(order.size()), static_cast<std::uint32_t>(level->size())});
    order.insert(order.end(), level->begin(), level->end());
  }
  upload(*gl_, buffers.levelOrder.emplace(*gl_), order);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  deformation_.refit(buffers, mesh, meshes_);
  return buffers;
}

Status ReflectionResources::prepare(int frameWidth, int frameHeight, glm::ivec2 margin, float texelsPerPixel,
                                    GBufferPrecision precision) {
  const glm::ivec2 covered(frameWidth + 2 * margin.x, frameHeight + 2 * margin.y);
  const glm::ivec2 size = glm::max(glm::ivec2(glm::round(glm::vec2(covered) * texelsPerPixel)), glm::ivec2(1));
  if (size == size_ && covered == coveredPixels_ && margin == margin_ && precision == precision_) return {};
  const GLsizei layers = static_cast<GLsizei>(std::max<std::size_t>(slots_.mirrors.size(), 1));
  GLint maxSize = 0;
  gl_->GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (size.x > maxSize || size.y > maxSize)
    return Error{"mirror G-buffer of " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                 " texels exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize) + "; lower the size or the margin"};
  size_ = size;
  margin_ = margin;
  coveredPixels_ = covered;
  precision_ = precision;
  coarseLevel_ = 0;
  while (std::max(levelSize(coarseLevel_).x, levelSize(coarseLevel_).y) > kCoarsestSide) ++coarseLevel_;
  // Textures are immutable once sized: replace them.
  position_ = gl::GlTexture(*gl_);
  normal_ = gl::GlTexture(*gl_);
  depth_ = gl::GlTexture(*gl_);
  for (const gl::GlTexture* texture : {&position_, &normal_}) {
    gl_->BindTexture(GL_TEXTURE_2D_ARRAY, texture->id());
    gl_->TexStorage3D(GL_TEXTURE_2D_ARRAY, coarseLevel_ + 1, textureFormat(), size.x, size.y, layers);
    gl_->TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    gl_->TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  surface_.reset();
  if (parametricMirror_) {
    surface_.emplace(*gl_);
    gl_->BindTexture(GL_TEXTURE_2D_ARRAY, surface_->id());
    gl_->TexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RGBA32F, size.x, size.y, layers);
    gl_->TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_->TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  gl_->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
  gl_->BindTexture(GL_TEXTURE_2D, depth_.id());
  gl_->TexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
  gl_->BindTexture(GL_TEXTURE_2D, 0);
  // Every layer starts empty: mark it all covered so the first frame clears it.
  std::fill(covered_.begin(), covered_.end(), TexelRect{{0, 0}, size});
  rayHierarchySpheres_.reset();
  rayHierarchyCones_.reset();
  return {};
}

void ReflectionResources::prepareRayHierarchy() {
  if (rayHierarchySpheres_) return;
  const GLsizei layers = static_cast<GLsizei>(std::max<std::size_t>(slots_.mirrors.size(), 1));
  rayHierarchyTop_ = 0;
  while (std::max(levelSize(rayHierarchyTop_).x, levelSize(rayHierarchyTop_).y) > 1) ++rayHierarchyTop_;
  rayHierarchySpheres_.emplace(*gl_);
  rayHierarchyCones_.emplace(*gl_);
  for (const gl::GlTexture* texture : {&*rayHierarchySpheres_, &*rayHierarchyCones_}) {
    gl_->BindTexture(GL_TEXTURE_2D_ARRAY, texture->id());
    gl_->TexStorage3D(GL_TEXTURE_2D_ARRAY, rayHierarchyTop_ + 1, GL_RGBA32F, size_.x, size_.y, layers);
    gl_->TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    gl_->TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  gl_->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
  // Undefined texels: the first build covers every leaf (the G-buffer is clear off its mirrors).
  rayHierarchyCovered_.assign(std::max<std::size_t>(slots_.mirrors.size(), 1), TexelRect{{0, 0}, size_});
}

void ReflectionResources::prepareExplosionMaps(int side) {
  if (explosionPositions_ && explosionSide_ == side) return;
  const GLsizei layers = static_cast<GLsizei>(2 * std::max<std::size_t>(slots_.mirrors.size(), 1));
  explosionSide_ = side;
  explosionPositions_.emplace(*gl_);
  explosionNormals_.emplace(*gl_);
  explosionDepth_.emplace(*gl_);
  for (const gl::GlTexture* texture : {&*explosionPositions_, &*explosionNormals_}) {
    gl_->BindTexture(GL_TEXTURE_2D_ARRAY, texture->id());
    gl_->TexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RGBA32F, side, side, layers);
    gl_->TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_->TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  gl_->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
  gl_->BindTexture(GL_TEXTURE_2D, explosionDepth_->id());
  gl_->TexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, side, side);
  gl_->BindTexture(GL_TEXTURE_2D, 0);
}

TexelRect ReflectionResources::takeRayHierarchyRebuild(int layer) {
  TexelRect& built = rayHierarchyCovered_[static_cast<std::size_t>(layer)];
  const TexelRect rebuild = built.united(covered_[static_cast<std::size_t>(layer)]);
  built = covered_[static_cast<std::size_t>(layer)];
  return rebuild;
}

glm::vec4 ReflectionResources::coveredFramePixels(int layer) const {
  // The G-buffer is the frame widened by the margin, at texelsPerPixel texels per pixel.
  const TexelRect& covered = covered_[static_cast<std::size_t>(layer)];
  const glm::vec2 margin(margin_);
  return glm::vec4(glm::vec2(covered.low) / texelsPerPixel() - margin,
                   glm::vec2(covered.high) / texelsPerPixel() - margin);
}

void ReflectionResources::resetCoherence() {
  // Unsolved last frame means "no seed": every vertex starts cold.
  ReflectedVertex unsolved{};
  unsolved.state.w = ReflectedVertex::kUnsolved;
  const std::vector<ReflectedVertex> initial(std::max<std::size_t>(slots_.slotCount, 1), unsolved);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, reflected_.id());
  gl_->BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(initial.size() * sizeof(ReflectedVertex)),
                     initial.data());
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

gl::GlBuffer ReflectionResources::exchangeReflectedVertices(std::optional<gl::GlBuffer> next) {
  gl::GlBuffer current = std::move(reflected_);
  if (next) {
    reflected_ = std::move(*next);
  } else {
    reflected_ = gl::GlBuffer(*gl_);
    allocateSlots(*gl_, reflected_, slots_.slotCount);
    resetCoherence();
  }
  return current;
}

void ReflectionResources::resetStatistics() {
  const SearchStatistics zero{};
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, statistics_.id());
  gl_->BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof zero, &zero);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

std::vector<ReflectedVertex> ReflectionResources::readReflectedVertices() const {
  std::vector<ReflectedVertex> result(slots_.slotCount);
  gl_->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, reflected_.id());
  gl_->GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(result.size() * sizeof(ReflectedVertex)),
                        result.data());
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  return result;
}

ReflectionResources::RayHierarchyLevel ReflectionResources::readRayHierarchyLevel(int level) const {
  RayHierarchyLevel result;
  if (!rayHierarchySpheres_ || level < 0 || level > rayHierarchyTop_) return result;
  result.size = levelSize(level);
  const std::size_t texels = static_cast<std::size_t>(result.size.x) * static_cast<std::size_t>(result.size.y) *
                             std::max<std::size_t>(slots_.mirrors.size(), 1);
  gl_->MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  for (auto [texture, out] :
       {std::pair{&*rayHierarchySpheres_, &result.spheres}, std::pair{&*rayHierarchyCones_, &result.cones}}) {
    out->resize(texels);
    gl_->BindTexture(GL_TEXTURE_2D_ARRAY, texture->id());
    gl_->GetTexImage(GL_TEXTURE_2D_ARRAY, level, GL_RGBA, GL_FLOAT, out->data());
  }
  gl_->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return result;
}

void bindGBufferTextures(const gl::GlApi& gl, const ReflectionResources& resources) {
  gl.ActiveTexture(GL_TEXTURE0 + kGBufferSurfaceUnit);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, resources.surfaceTexture());
  gl.ActiveTexture(GL_TEXTURE1);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, resources.normalTexture());
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, resources.positionTexture());
}

void setGBufferSamplers(const gl::ShaderProgram& program) {
  program.set("gbufferPosition", 0);
  program.set("gbufferNormal", 1);
}

void setGBufferPixelMapping(const gl::ShaderProgram& program, const ReflectionResources& resources) {
  program.set("marginPixels", glm::vec2(resources.margin()));
  program.set("texelsPerPixel", resources.texelsPerPixel());
}

}  // namespace specula::passes
