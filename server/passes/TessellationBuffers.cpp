#include "passes/TessellationBuffers.h"

#include <algorithm>

namespace specula::passes {

TessellationBuffers::TessellationBuffers(const gl::GlApi& gl)
    : gl_(&gl),
      working_{{gl::GlBuffer(gl)}, {gl::GlBuffer(gl)}},
      finished_{gl::GlBuffer(gl)},
      splits_{gl::GlBuffer(gl)},
      requests_{gl::GlBuffer(gl)},
      requestCounts_{gl::GlBuffer(gl)},
      counters_(gl), midpointStatistics_(gl) {
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, midpointStatistics_.id());
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, sizeof(SearchStatistics), nullptr, GL_DYNAMIC_READ);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void TessellationBuffers::beginFrame() {
  finishedCount_ = 0;
  ranges_.clear();
  statistics_ = {};
  const SearchStatistics zero{};
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, midpointStatistics_.id());
  gl_->BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof zero, &zero);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void TessellationBuffers::reserve(GrowingBuffer& target, std::size_t bytes, std::size_t keepBytes) {
  if (bytes <= target.capacityBytes) return;
  // Grow by half again, so a slowly growing frame does not reallocate every round.
  const std::size_t capacity = std::max(bytes, target.capacityBytes + target.capacityBytes / 2);
  gl::GlBuffer grown(*gl_);
  gl_->BindBuffer(GL_COPY_WRITE_BUFFER, grown.id());
  gl_->BufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_COPY);
  if (keepBytes > 0) {
    gl_->BindBuffer(GL_COPY_READ_BUFFER, target.buffer.id());
    gl_->CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, static_cast<GLsizeiptr>(keepBytes));
    gl_->BindBuffer(GL_COPY_READ_BUFFER, 0);
  }
  gl_->BindBuffer(GL_COPY_WRITE_BUFFER, 0);
  target.buffer = std::move(grown);
  target.capacityBytes = capacity;
}

bool TessellationBuffers::reserveWorking(int list, std::size_t triangles) {
  if (triangles > kMaxTriangles) return false;
  reserve(working_[list], triangles * kTriangleBytes, 0);
  return true;
}

bool TessellationBuffers::reserveSplits(std::size_t triangles) {
  if (triangles > kMaxTriangles) return false;
  reserve(splits_, triangles * kSplitBytes, 0);
  return true;
}

bool TessellationBuffers::reserveRequests(std::size_t triangles, std::size_t runs) {
  if (triangles > kMaxTriangles) return false;
  reserve(requests_, std::max<std::size_t>(triangles, 1) * kRequestBytes, 0);
  const std::vector<std::uint32_t> zero(4 * std::max<std::size_t>(runs, 1), 0);
  reserve(requestCounts_, zero.size() * sizeof(std::uint32_t), 0);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, requestCounts_.buffer.id());
  gl_->BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(zero.size() * sizeof(std::uint32_t)), zero.data());
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  return true;
}

bool TessellationBuffers::reserveFinished(std::size_t more) {
  const std::size_t total = finishedCount_ + more;
  if (total > kMaxTriangles) return false;
  reserve(finished_, total * kTriangleBytes, finishedCount_ * kTriangleBytes);
  return true;
}

void TessellationBuffers::resetCounters(std::size_t objects) {
  const std::vector<RoundCounts> zero(std::max<std::size_t>(objects, 1));
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, counters_.id());
  if (zero.size() > counterCapacity_) {
    counterCapacity_ = zero.size();
    gl_->BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(counterCapacity_ * sizeof(RoundCounts)), nullptr, GL_DYNAMIC_READ);
  }
  gl_->BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(zero.size() * sizeof(RoundCounts)), zero.data());
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

std::vector<TessellationBuffers::RoundCounts> TessellationBuffers::readCounters(std::size_t objects) const {
  std::vector<RoundCounts> counts(objects);
  gl_->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, counters_.id());
  gl_->GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(objects * sizeof(RoundCounts)), counts.data());
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  return counts;
}

std::vector<FinishedVertex> TessellationBuffers::readFinished() const {
  std::vector<TessellatedVertex> records(3 * finishedCount_);
  if (!records.empty()) {
    gl_->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, finished());
    gl_->GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(records.size() * kRecordBytes), records.data());
    gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  }
  std::vector<FinishedVertex> vertices;
  for (const TessellatedRange& range : ranges_) {
    if (range.fromMesh) continue;
    for (GLsizei k = 0; k < 3 * range.triangles; ++k)
      vertices.push_back({range.mirror->mirrorObject, range.mirror->part, records[static_cast<std::size_t>(3 * range.firstTriangle + k)]});
  }
  return vertices;
}

const TessellationStatistics& TessellationBuffers::finishStatistics() {
  gl_->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, midpointStatistics_.id());
  gl_->GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(SearchStatistics), &statistics_.midpointSearches);
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  statistics_.finishedTriangles += static_cast<std::uint32_t>(finishedCount_);  // the meshes drawn whole were counted already
  return statistics_;
}

}  // namespace specula::passes
