// A frame waits for the GPU once, to read its image: tessellation's rounds size and launch each other
// on the GPU, and the statistics are copied out before the image is read and read after it. Counted
// through a wrapper around every GL entry point that reads back or waits.
#include <gtest/gtest.h>

#include <string>

#include "gl/GlContext.h"
#include "render/Renderer.h"
#include "scene/ScenePose.h"
#include "SceneRig.h"

using namespace specula;
using specula::testing::makeRig;
using specula::testing::Rig;

namespace {

// Calls that make the CPU wait for the GPU, by entry point.
struct Waits {
  int readPixels = 0, textureReads = 0, bufferReads = 0, mapsForReading = 0, finishes = 0, fenceWaits = 0,
      queryResults = 0;
  int besidesTheImage() const {
    return textureReads + bufferReads + mapsForReading + finishes + fenceWaits + queryResults;
  }
};

Waits waits;
gl::GlApi original;

void APIENTRY countReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels) {
  ++waits.readPixels;
  original.ReadPixels(x, y, w, h, format, type, pixels);
}
void APIENTRY countGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
  ++waits.textureReads;
  original.GetTexImage(target, level, format, type, pixels);
}
void APIENTRY countGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  ++waits.bufferReads;
  original.GetBufferSubData(target, offset, size, data);
}
void* APIENTRY countMapBufferRange(GLenum target, GLintptr offset, GLsizeiptr length, GLbitfield access) {
  // Mapped for good (persistent) is not a read: reading the memory after a fence has passed is.
  if ((access & GL_MAP_READ_BIT) != 0 && (access & GL_MAP_PERSISTENT_BIT) == 0) ++waits.mapsForReading;
  return original.MapBufferRange(target, offset, length, access);
}
void APIENTRY countFinish() {
  ++waits.finishes;
  original.Finish();
}
GLenum APIENTRY countClientWaitSync(GLsync sync, GLbitfield flags, GLuint64 timeout) {
  const GLenum state = original.ClientWaitSync(sync, flags, timeout);
  if (timeout > 0) ++waits.fenceWaits;  // a zero timeout only asks
  return state;
}
void APIENTRY countGetQueryObjectui64v(GLuint id, GLenum name, GLuint64* value) {
  if (name == GL_QUERY_RESULT) ++waits.queryResults;
  original.GetQueryObjectui64v(id, name, value);
}

// Counts, while it lives, the waiting calls made through the context's function table.
class WaitCounter {
 public:
  explicit WaitCounter(gl::GlContext& context) : api_(context.apiToInstrument()) {
    original = api_;
    waits = {};
    api_.ReadPixels = countReadPixels;
    api_.GetTexImage = countGetTexImage;
    api_.GetBufferSubData = countGetBufferSubData;
    api_.MapBufferRange = countMapBufferRange;
    api_.Finish = countFinish;
    api_.ClientWaitSync = countClientWaitSync;
    api_.GetQueryObjectui64v = countGetQueryObjectui64v;
  }
  ~WaitCounter() { api_ = original; }

 private:
  gl::GlApi& api_;
};

}  // namespace

// Every mirror kind's searched and tessellated frame: a convex sphere, the kitchen's bowl (concave,
// two parts, sees itself), a faceted mesh sphere and the Utah teapot's Bézier patches (six parts).
TEST(FrameSync, ASearchedTessellatedFrameWaitsOnlyToReadItsImage) {
  for (const char* sceneName : {"checker-sphere", "kitchen", "mesh-sphere", "utah-teapot"}) {
    SCOPED_TRACE(sceneName);
    Rig rig = makeRig(sceneName);
    ASSERT_TRUE(rig.renderer);
    rig.renderer->setPassTiming(render::PassTiming::FrameOnly);
    const scene::Scene& scene = rig.renderer->scene();
    const passes::ReflectionSettings searched = specula::testing::virtualObjects();
    // The first frames size the lists and the statistics' staging buffer.
    for (int i = 0; i < 2; ++i)
      ASSERT_TRUE(rig.renderer->render(scene::ScenePose::at(scene, 0.1 * i), 320, 240, searched));
    WaitCounter counter(*rig.context);
    auto frame = rig.renderer->render(scene::ScenePose::at(scene, 0.2), 320, 240, searched);
    ASSERT_TRUE(frame) << frame.error();
    EXPECT_EQ(waits.readPixels, 1) << "the image";
    EXPECT_EQ(waits.besidesTheImage(), 0)
        << "buffer reads " << waits.bufferReads << ", texture reads " << waits.textureReads << ", maps "
        << waits.mapsForReading << ", glFinish " << waits.finishes << ", fence waits " << waits.fenceWaits
        << ", query results " << waits.queryResults;
    // What the frame did still arrives with it.
    EXPECT_GT(frame->search.searched, 0u);
    EXPECT_GE(frame->tessellation.trianglesPerRound.size(), 2u) << "something split";
    EXPECT_GT(frame->tessellation.midpointSearches.searched, 0u);
    EXPECT_GT(frame->tessellation.finishedTriangles, 0u);
  }
}

// The counter sees what it should: per-pass timing on a CPU rasterizer waits after every pass, and
// a read of the finished triangles is a buffer read.
TEST(FrameSync, TheCounterSeesPerPassTimingAndReadbacks) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  const passes::ReflectionSettings searched = specula::testing::virtualObjects();
  ASSERT_TRUE(rig.renderer->render(pose, 320, 240, searched));
  WaitCounter counter(*rig.context);
  ASSERT_TRUE(rig.renderer->render(pose, 320, 240, searched));
  const bool cpuRasterizer = rig.context->info().renderer.find("llvmpipe") != std::string::npos;
  EXPECT_GE(cpuRasterizer ? waits.finishes : waits.queryResults, 7) << "a wait per pass";
  EXPECT_FALSE(rig.renderer->readTessellatedVertices().empty());
  EXPECT_GE(waits.bufferReads, 2);
}
