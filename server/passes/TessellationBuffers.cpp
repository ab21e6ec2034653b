#include "passes/TessellationBuffers.h"

#include <algorithm>

namespace specula::passes {

namespace {
// Lists start with room for this many triangles at least, so a small scene never grows them.
constexpr std::size_t kInitialTriangles = std::size_t{1} << 14;

// (Re)allocates `buffer` to `bytes`, content undefined.
void allocate(const gl::GlApi& gl, const gl::GlBuffer& buffer, std::size_t bytes, const void* data = nullptr) {
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, buffer.id());
  gl.BufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 4)), data, GL_DYNAMIC_COPY);
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, 0);
}

// Grows a capacity by half again at least, so a slowly growing scene does not reallocate every frame.
std::size_t grown(std::size_t capacity, std::size_t needed) {
  return std::min(TessellationBuffers::kMaxTriangles, std::max(needed, capacity + capacity / 2));
}
}  // namespace

TessellationBuffers::TessellationBuffers(const gl::GlApi& gl)
    : gl_(&gl),
      working_{gl::GlBuffer(gl), gl::GlBuffer(gl)},
      finished_(gl),
      splits_(gl),
      requests_(gl),
      runRecords_(gl),
      draws_(gl),
      totals_(gl),
      midpointStatistics_(gl) {
  allocate(gl, totals_, sizeof(gpu::TessellationTotals));
  allocate(gl, midpointStatistics_, sizeof(SearchStatistics));
}

void TessellationBuffers::beginFrame(std::vector<TessellatedRun> runs, const std::vector<gpu::TessellationRun>& records,
                                     const std::vector<gpu::RunDraws>& draws, std::size_t largestPart) {
  const gl::GlApi& gl = *gl_;
  runs_ = std::move(runs);
  statistics_ = {};
  std::size_t roundInput = 0;
  for (const gpu::TessellationRun& record : records) roundInput += record.work[0].count;
  inputTriangles_ = predictedUnsplitObjects_ = predictedUnsplitTriangles_ = 0;
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    const std::uint32_t triangles = draws[i].mesh.count / 3;
    inputTriangles_ += triangles;
    if (runs_[i].rounds) continue;
    ++predictedUnsplitObjects_;
    predictedUnsplitTriangles_ += triangles;
  }
  const std::size_t working = std::min(kMaxTriangles, std::max({workingCapacity_, 2 * largestPart, kInitialTriangles}));
  if (working != workingCapacity_) {
    for (const gl::GlBuffer& list : working_) allocate(gl, list, working * kTriangleBytes);
    workingCapacity_ = working;
  }
  // Round 0 numbers a part's mesh triangles run after run, later rounds their places in a working list.
  const std::size_t splits = std::max(workingCapacity_, std::min(largestPart, kMaxTriangles));
  if (splits > splitCapacity_) {
    allocate(gl, splits_, splits * kSplitBytes);
    allocate(gl, requests_, splits * kRequestBytes);
    splitCapacity_ = splits;
  }
  const std::size_t finished =
      std::min(kMaxTriangles, std::max({finishedCapacity_, 2 * roundInput, kInitialTriangles}));
  if (finished != finishedCapacity_) {
    allocate(gl, finished_, finished * kTriangleBytes);
    finishedCapacity_ = finished;
  }
  if (records.size() > runCapacity_) {
    runCapacity_ = records.size();
    allocate(gl, runRecords_, runCapacity_ * sizeof(gpu::TessellationRun));
    allocate(gl, draws_, runCapacity_ * sizeof(gpu::RunDraws));
  }
  const gpu::TessellationTotals noTotals{};
  const SearchStatistics noSearches{};
  const auto upload = [&](const gl::GlBuffer& buffer, std::size_t bytes, const void* data) {
    if (bytes == 0) return;
    gl.BindBuffer(GL_COPY_WRITE_BUFFER, buffer.id());
    gl.BufferSubData(GL_COPY_WRITE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
    gl.BindBuffer(GL_COPY_WRITE_BUFFER, 0);
  };
  upload(runRecords_, records.size() * sizeof(gpu::TessellationRun), records.data());
  upload(draws_, draws.size() * sizeof(gpu::RunDraws), draws.data());
  upload(totals_, sizeof noTotals, &noTotals);
  upload(midpointStatistics_, sizeof noSearches, &noSearches);
}

bool TessellationBuffers::finishFrame(const gpu::TessellationTotals& totals, const SearchStatistics& midpoints) {
  statistics_.inputTriangles = inputTriangles_;
  statistics_.predictedUnsplitObjects = predictedUnsplitObjects_;
  statistics_.midpointSearches = midpoints;
  statistics_.capped = totals.capped != 0;
  statistics_.finishedTriangles = totals.finished + totals.meshTriangles + predictedUnsplitTriangles_;
  // Rounds no triangle entered are not reported (the CPU launched them, empty, not knowing).
  std::size_t rounds = TESSELLATION_MAX_ROUNDS;
  while (rounds > 0 && totals.trianglesPerRound[rounds - 1] == 0) --rounds;
  statistics_.trianglesPerRound.assign(totals.trianglesPerRound, totals.trianglesPerRound + rounds);
  bool outgrown = false;
  if (totals.neededWorking > workingCapacity_ && workingCapacity_ < kMaxTriangles) {
    const std::size_t working = grown(workingCapacity_, totals.neededWorking);
    for (const gl::GlBuffer& list : working_) allocate(*gl_, list, working * kTriangleBytes);
    workingCapacity_ = working;
    outgrown = true;
  }
  if (totals.neededFinished > finishedCapacity_ && finishedCapacity_ < kMaxTriangles) {
    finishedCapacity_ = grown(finishedCapacity_, totals.neededFinished);
    allocate(*gl_, finished_, finishedCapacity_ * kTriangleBytes);
    outgrown = true;
  }
  return outgrown;
}

std::vector<FinishedVertex> TessellationBuffers::readFinished() const {
  std::vector<FinishedVertex> vertices;
  if (runs_.empty()) return vertices;
  const gl::GlApi& gl = *gl_;
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<gpu::RunDraws> draws(runs_.size());
  gl.BindBuffer(GL_COPY_READ_BUFFER, draws_.id());
  gl.GetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(draws.size() * sizeof(gpu::RunDraws)),
                      draws.data());
  std::size_t records = 0;
  for (const gpu::RunDraws& run : draws)
    for (const gpu::DrawArraysCommand& round : run.rounds)
      records = std::max<std::size_t>(records, round.first + round.count);
  std::vector<TessellatedVertex> finished(records);
  if (!finished.empty()) {
    gl.BindBuffer(GL_COPY_READ_BUFFER, finished_.id());
    gl.GetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(records * kRecordBytes), finished.data());
  }
  gl.BindBuffer(GL_COPY_READ_BUFFER, 0);
  for (std::size_t i = 0; i < runs_.size(); ++i)
    for (const gpu::DrawArraysCommand& round : draws[i].rounds)
      for (std::uint32_t k = 0; k < round.count; ++k)
        vertices.push_back({runs_[i].mirror->mirrorObject, runs_[i].mirror->part, finished[round.first + k]});
  return vertices;
}

}  // namespace specula::passes
