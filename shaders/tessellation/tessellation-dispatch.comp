#version 440 core
// Between classify and search, per object of the round: the search's work-group count from its
// number of requests, so the search dispatches indirectly and the CPU waits for nothing.
layout(local_size_x = 64) in;

struct RunRequests {
  uint count;
  uint searchGroups[3];
};
layout(std430, binding = 8) buffer RequestCounts {
  RunRequests runs[];
};

uniform uint runCount;

void main() {
  uint run = gl_GlobalInvocationID.x;
  if (run >= runCount) return;
  runs[run].searchGroups[0] = (runs[run].count + 63u) / 64u;  // local_size_x of tessellation-search.comp
  runs[run].searchGroups[1] = 1u;
  runs[run].searchGroups[2] = 1u;
}
