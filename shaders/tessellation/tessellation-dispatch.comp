#version 440 core
// Between classify and search, per run of the round: the search's work-group count from its number
// of requests, so the search dispatches indirectly and the CPU waits for nothing.
#include "common/tessellation-records.glsl"

layout(local_size_x = TESSELLATION_GROUP_SIZE) in;

layout(std430, binding = TESSELLATION_RUNS_BINDING) buffer TessellationRuns {
  TessellationRun runs[];
};

uniform uint firstRun;  // the part's runs: [firstRun, firstRun + runCount)
uniform uint runCount;

void main() {
  if (gl_GlobalInvocationID.x >= runCount) return;
  uint run = firstRun + gl_GlobalInvocationID.x;
  runs[run].searchGroups[0] = (runs[run].requestCount + uint(TESSELLATION_GROUP_SIZE) - 1u) / uint(TESSELLATION_GROUP_SIZE);
  runs[run].searchGroups[1] = 1u;
  runs[run].searchGroups[2] = 1u;
}
