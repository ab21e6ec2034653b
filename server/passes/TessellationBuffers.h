#pragma once
// GPU buffers of adaptive tessellation (shaders/tessellation): two working lists that rounds
// ping-pong between, the finished list the virtual-objects pass draws, the per-triangle split
// decisions and the round's counters. Lists are triangle soups of TessellatedVertex records
// (shaders/common/tessellated-vertex.glsl). Buffers grow on demand up to a cap; past the cap
// triangles stop splitting, and the frame says so, instead of failing.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/GlApi.h"
#include "gl/GlObject.h"
#include "passes/ReflectedVertex.h"
#include "passes/ReflectionSlots.h"

namespace specula::passes {

// Finished triangles of one reflected object in one mirror part (one range per round that finished some).
struct TessellatedRange {
  const MirrorSlots* mirror = nullptr;  // the part they reflect in
  const ReflectionSlotRange* object = nullptr;  // the reflected object and its search slots
  GLint firstTriangle = 0;
  GLsizei triangles = 0;
  bool fromMesh = false;  // nothing split: draw the object's own mesh with its search slots
};

// CPU view of one record of the lists: the std430 twin of TessellatedVertex in
// shaders/common/tessellated-vertex.glsl.
struct TessellatedVertex {
  glm::vec4 positionU;         // world position, u
  glm::vec4 normalV;           // world normal, v
  glm::vec4 virtualFlags;      // virtual position, flags (ReflectedVertex::k...)
  glm::vec4 reflectionTexelX;  // reflection point R, its texel's x
  glm::vec4 normalTexelY;      // normal at R, its texel's y
};
static_assert(sizeof(TessellatedVertex) == 80, "must match tessellated-vertex.glsl");

// A finished vertex and the mirror it was reflected in (what tests measure against exact answers).
struct FinishedVertex {
  std::size_t mirrorObject = 0;
  int part = 0;  // of the mirror (MirrorSlots::part)
  TessellatedVertex record;
};

struct TessellationStatistics {
  std::uint32_t inputTriangles = 0;                 // reflected objects' triangles, summed over mirrors
  std::vector<std::uint32_t> trianglesPerRound;     // working triangles entering each round
  std::uint32_t finishedTriangles = 0;              // triangles the virtual-objects pass draws
  SearchStatistics midpointSearches;                // the searches for new edge midpoints
  bool capped = false;                              // a list reached kMaxTriangles: splitting stopped early
  std::uint32_t predictedUnsplitObjects = 0;        // drawn from their meshes without a round (PlannedMirror::tessellated)
};

class TessellationBuffers {
 public:
  static constexpr std::size_t kRecordBytes = sizeof(TessellatedVertex);
  static constexpr std::size_t kTriangleBytes = 3 * kRecordBytes;
  static constexpr std::size_t kSplitBytes = 3 * kRecordBytes + 32;  // one EdgeSplit
  static constexpr std::size_t kRequestBytes = 3 * sizeof(std::uint32_t);  // a triangle's edge requests, at most
  static constexpr std::size_t kRunRequestBytes = 4 * sizeof(std::uint32_t);  // RunRequests: count, indirect dispatch
  static constexpr std::size_t kMaxTriangles = std::size_t{1} << 20;  // per list: 240 MiB

  explicit TessellationBuffers(const gl::GlApi& gl);

  // Forgets last frame's lists and zeroes the statistics.
  void beginFrame();
  // Make room for `triangles` in working list `list` (content not kept) or, for split decisions,
  // in the split buffer; false past kMaxTriangles.
  bool reserveWorking(int list, std::size_t triangles);
  bool reserveSplits(std::size_t triangles);
  // Room for the edge requests of `triangles` working triangles, split into `runs` lists, whose
  // counts start at zero.
  bool reserveRequests(std::size_t triangles, std::size_t runs);
  // Make room for `more` finished triangles after the current ones, keeping them.
  bool reserveFinished(std::size_t more);

  GLuint working(int list) const { return working_[list].buffer.id(); }
  GLuint finished() const { return finished_.buffer.id(); }
  GLuint splits() const { return splits_.buffer.id(); }
  GLuint requests() const { return requests_.buffer.id(); }
  GLuint requestCounts() const { return requestCounts_.buffer.id(); }
  GLuint counters() const { return counters_.id(); }
  GLuint midpointStatistics() const { return midpointStatistics_.id(); }
  std::size_t finishedCount() const { return finishedCount_; }
  void addFinished(std::size_t triangles) { finishedCount_ += triangles; }

  // Per object of a round: the triangles its split ones become and those finished. Zeroes them
  // before a round; reads them after it (one readback for every object).
  struct RoundCounts {
    std::uint32_t children = 0, unsplit = 0;
  };
  void resetCounters(std::size_t objects);
  std::vector<RoundCounts> readCounters(std::size_t objects) const;

  // Every vertex of the finished lists, with its mirror (a GPU readback; ranges drawn from meshes
  // have no records: their vertices are the search slots').
  std::vector<FinishedVertex> readFinished() const;

  std::vector<TessellatedRange>& ranges() { return ranges_; }
  const std::vector<TessellatedRange>& ranges() const { return ranges_; }
  TessellationStatistics& statistics() { return statistics_; }
  // Fills in the midpoint search totals (a GPU readback) and returns the frame's statistics.
  const TessellationStatistics& finishStatistics();

 private:
  struct GrowingBuffer {
    gl::GlBuffer buffer;
    std::size_t capacityBytes = 0;
  };
  void reserve(GrowingBuffer& target, std::size_t bytes, std::size_t keepBytes);

  const gl::GlApi* gl_;
  GrowingBuffer working_[2], finished_, splits_, requests_, requestCounts_;
  gl::GlBuffer counters_, midpointStatistics_;
  std::size_t counterCapacity_ = 0;  // objects
  std::size_t finishedCount_ = 0;
  std::vector<TessellatedRange> ranges_;
  TessellationStatistics statistics_;
};

}  // namespace specula::passes
