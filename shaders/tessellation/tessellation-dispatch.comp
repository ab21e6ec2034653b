#version 440 core
// Between classify and search: the search's work-group count from its number of requests (per run
// in round 0, for the part later), so the search dispatches indirectly and the CPU waits for nothing.
#include "common/tessellation-records.glsl"

layout(local_size_x = TESSELLATION_GROUP_SIZE) in;

layout(std430, binding = TESSELLATION_RUNS_BINDING) buffer TessellationRuns {
  TessellationRun runs[];
};
layout(std430, binding = TESSELLATION_TOTALS_BINDING) buffer Totals {
  TessellationTotals totals;
};

uniform int fromMesh;  // round 0: each run's search; later the part's, one dispatch

uniform uint firstRun;  // the part's runs: [firstRun, firstRun + runCount)
uniform uint runCount;

uint groupsFor(uint count) { return (count + uint(TESSELLATION_GROUP_SIZE) - 1u) / uint(TESSELLATION_GROUP_SIZE); }

void main() {
  if (fromMesh == 0) {
    if (gl_GlobalInvocationID.x == 0u) totals.partSearchGroups = uint[3](groupsFor(totals.partRequests), 1u, 1u);
    return;
  }
  if (gl_GlobalInvocationID.x >= runCount) return;
  uint run = firstRun + gl_GlobalInvocationID.x;
  runs[run].searchGroups = uint[3](groupsFor(runs[run].requestCount), 1u, 1u);
}
