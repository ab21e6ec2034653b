#version 440 core
// Round step 4, once per part and round, on one invocation: from what decide counted, whether the
// part's triangles split further or finish here, and where each run's finished triangles and
// children go. Writes the draws of what finishes and the next round's work and indirect dispatch,
// so no count returns to the CPU between rounds. Runs are laid out in order, so a frame is the same
// whatever order the GPU ran its triangles in.
#include "common/tessellation-records.glsl"

layout(local_size_x = 1) in;

layout(std430, binding = TESSELLATION_RUNS_BINDING) buffer TessellationRuns {
  TessellationRun runs[];
};
layout(std430, binding = TESSELLATION_DRAWS_BINDING) buffer TessellationDraws {
  RunDraws draws[];
};
layout(std430, binding = TESSELLATION_TOTALS_BINDING) buffer Totals {
  TessellationTotals totals;
};

uniform uint firstRun;          // the part's runs: [firstRun, firstRun + runCount)
uniform uint runCount;
uniform uint round;              // 0: the meshes' own triangles
uniform uint parity;             // the round's work: work[parity]; the next round's: the other
uniform int lastRound;           // 1 at the deepest level: nothing splits
uniform uint partsLeft;          // this part and those after it in the frame
uniform uint maxTriangles;       // the cap of every list (TessellationBuffers::kMaxTriangles)
uniform uint workingCapacity;    // triangles each working list has room for this frame
uniform uint finishedCapacity;   // and the finished list

void drawFromMesh(uint run) {
  runs[run].drawnFromMesh = 1u;
  draws[run].mesh.instanceCount = 1u;
  totals.meshTriangles += draws[run].mesh.count / 3u;  // the mesh's triangles
}

void main() {
  uint next = 1u - parity;
  // Each part may take an even share of what is left of the finished list, so one part's full
  // tessellation cannot leave the next none.
  if (round == 0u) totals.partBudget = totals.finished + (maxTriangles - totals.finished) / partsLeft;
  uint total = 0u, children = 0u, unsplit = 0u;
  for (uint run = firstRun; run < firstRun + runCount; ++run) {
    if (runs[run].drawnFromMesh != 0u) continue;
    // Round 0: an object none of whose triangles splits is drawn from its mesh, copied nowhere.
    if (round == 0u && runs[run].children == 0u && runs[run].work[parity].count > 0u) {
      totals.trianglesPerRound[0] += runs[run].work[parity].count;
      drawFromMesh(run);
      continue;
    }
    total += runs[run].work[parity].count;
    children += runs[run].children;
    unsplit += runs[run].unsplit;
  }
  totals.trianglesPerRound[round] += total;

  // Past the cap or this part's share of the finished list: the working triangles finish here
  // (they fit the share, since the last round's check counted them as children).
  bool last = lastRound != 0;
  if (!last && children > 0u && (totals.finished + unsplit + children > totals.partBudget || children > maxTriangles)) {
    last = true;
    totals.capped = 1u;
  }
  // Past this frame's room but under the cap: the renderer grows the lists and renders the frame again.
  if (!last && children > workingCapacity) {
    totals.neededWorking = max(totals.neededWorking, children);
    last = true;
  }
  if (last) unsplit = total;
  bool overCap = totals.finished + unsplit > maxTriangles;
  if (overCap || totals.finished + unsplit > finishedCapacity) {
    // No room in the finished list: these objects are drawn whole from their meshes, over what
    // earlier rounds finished of them. Per-pixel exact hits make the overlap draw the same pixels
    // twice, so only coverage is coarser, where dropping the round left holes.
    if (overCap) totals.capped = 1u;
    else totals.neededFinished = max(totals.neededFinished, totals.finished + unsplit);
    for (uint run = firstRun; run < firstRun + runCount; ++run)
      if (runs[run].drawnFromMesh == 0u && runs[run].work[parity].count > 0u) drawFromMesh(run);
  }

  uint childrenTotal = 0u;
  for (uint run = firstRun; run < firstRun + runCount; ++run) {
    uint count = runs[run].drawnFromMesh != 0u ? 0u : runs[run].work[parity].count;
    uint runChildren = last || count == 0u ? 0u : runs[run].children;
    uint runFinished = last ? count : (count == 0u ? 0u : runs[run].unsplit);
    runs[run].finishAll = last ? 1u : 0u;
    runs[run].finishedBase = totals.finished;
    runs[run].childrenBase = childrenTotal;
    draws[run].rounds[round] = DrawArraysCommand(3u * runFinished, 1u, 3u * totals.finished, 0u);
    totals.finished += runFinished;
    runs[run].work[next] = RunWork(childrenTotal, runChildren);
    childrenTotal += runChildren;
    // Decide's counts are spent: zeroed for the next round, and emit's places start at zero.
    runs[run].requestCount = 0u;
    runs[run].children = 0u;
    runs[run].unsplit = 0u;
    runs[run].childrenPlaced = 0u;
    runs[run].finishedPlaced = 0u;
  }
  // The next round runs each kernel once over every run's children.
  totals.part[next] = PartWork(childrenTotal, uint[3]((childrenTotal + uint(TESSELLATION_GROUP_SIZE) - 1u) / uint(TESSELLATION_GROUP_SIZE), 1u, 1u));
  totals.partRequests = 0u;
}
