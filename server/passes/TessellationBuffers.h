#pragma once
// GPU buffers of adaptive tessellation (shaders/tessellation): two working lists that rounds
// ping-pong between, the finished list the virtual-objects pass draws, the per-triangle split
// decisions, and the run records (common/tessellation-records.glsl) through which the GPU sizes and
// launches each round and draws what it finished, so no count returns to the CPU within a frame.
// Lists are triangle soups of TessellatedVertex records (shaders/common/tessellated-vertex.glsl).
// The lists keep their size from frame to frame; a frame that outgrows them is reported by its
// totals (read once the frame is done), and the renderer grows them and renders it again, up to
// the cap, past which triangles stop splitting and the frame says so.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/tessellation-records.glsl"
#include "gl/GlApi.h"
#include "gl/GlObject.h"
#include "passes/ReflectedVertex.h"
#include "passes/ReflectionSlots.h"

namespace specula::passes {

// One reflected object of one mirror part, as tessellation hands it to the virtual-objects pass:
// drawn from its mesh or from the finished list, as the GPU's records for run `run` say.
struct TessellatedRun {
  const MirrorSlots* mirror = nullptr;          // the part it reflects in
  const ReflectionSlotRange* object = nullptr;  // the reflected object and its search slots
  bool rounds = false;                          // false: predicted unsplit, drawn from its mesh with no round
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
  std::uint32_t inputTriangles = 0;              // reflected objects' triangles, summed over mirrors
  std::vector<std::uint32_t> trianglesPerRound;  // working triangles entering each round
  std::uint32_t finishedTriangles = 0;           // triangles the virtual-objects pass draws
  SearchStatistics midpointSearches;             // the searches for new edge midpoints
  bool capped = false;                           // a list reached kMaxTriangles: splitting stopped early
  std::uint32_t predictedUnsplitObjects = 0;     // drawn from their meshes without a round (PlannedMirror::tessellated)
};

class TessellationBuffers {
 public:
  static constexpr std::size_t kRecordBytes = sizeof(TessellatedVertex);
  static constexpr std::size_t kTriangleBytes = 3 * kRecordBytes;
  static constexpr std::size_t kSplitBytes = 3 * kRecordBytes + 32;        // one EdgeSplit
  static constexpr std::size_t kRequestBytes = 3 * sizeof(std::uint32_t);  // a triangle's edge requests, at most
  static constexpr std::size_t kMaxTriangles = std::size_t{1} << 20;       // per list: 240 MiB

  explicit TessellationBuffers(const gl::GlApi& gl);

  // Starts a frame whose runs are `runs` (each part's in a row) with these round-0 records and
  // draws; `largestPart`: the most triangles one part's runs bring into round 0. Zeroes the totals.
  void beginFrame(std::vector<TessellatedRun> runs, const std::vector<gpu::TessellationRun>& records,
                  const std::vector<gpu::RunDraws>& draws, std::size_t largestPart);

  GLuint working(int list) const { return working_[list].id(); }
  GLuint finished() const { return finished_.id(); }
  GLuint splits() const { return splits_.id(); }
  GLuint requests() const { return requests_.id(); }
  GLuint runs() const { return runRecords_.id(); }
  GLuint draws() const { return draws_.id(); }
  GLuint totals() const { return totals_.id(); }
  GLuint midpointStatistics() const { return midpointStatistics_.id(); }
  std::size_t workingCapacity() const { return workingCapacity_; }
  std::size_t finishedCapacity() const { return finishedCapacity_; }
  const std::vector<TessellatedRun>& frameRuns() const { return runs_; }

  // The frame's statistics from its totals and midpoint-search totals as read back once the frame
  // was done (`totals`, `midpoints`); grows the lists for the next frame when the totals say this
  // one outgrew them, and then returns true: the frame must be rendered again to be whole.
  bool finishFrame(const gpu::TessellationTotals& totals, const SearchStatistics& midpoints);
  const TessellationStatistics& statistics() const { return statistics_; }

  // Every vertex of the finished lists, with its mirror (a GPU readback, outside the frame; runs
  // drawn from meshes have no records: their vertices are the search slots').
  std::vector<FinishedVertex> readFinished() const;

 private:
  const gl::GlApi* gl_;
  gl::GlBuffer working_[2], finished_, splits_, requests_, runRecords_, draws_, totals_, midpointStatistics_;
  std::size_t workingCapacity_ = 0, finishedCapacity_ = 0, splitCapacity_ = 0;  // triangles
  std::size_t runCapacity_ = 0;
  std::vector<TessellatedRun> runs_;
  // This frame's, known before it: every run's triangles, and those of runs with no round.
  std::uint32_t inputTriangles_ = 0, predictedUnsplitObjects_ = 0, predictedUnsplitTriangles_ = 0;
  TessellationStatistics statistics_;
};

}  // namespace specula::passes
