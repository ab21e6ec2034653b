// The GPU records that drive adaptive tessellation's rounds with no read back to the CPU, one
// definition for C++ (passes/TessellationBuffers, passes/TessellationPass,
// passes/VirtualObjectsPass) and GLSL (shaders/tessellation, virtual-objects).
// Each reflected object of a mirror part that goes through the rounds is a run: its working
// triangles, its counters and the indirect commands that launch and draw its next step.
#ifdef __cplusplus
#pragma once
#include <cstdint>
namespace specula::passes::gpu {
using uint = std::uint32_t;
#endif

#define TESSELLATION_GROUP_SIZE 64  // local_size_x of every per-triangle and per-request kernel
// Rounds a frame runs at most: level 0 (the meshes) to the deepest level the settings allow.
#define TESSELLATION_MAX_ROUNDS 9

// Storage-buffer bindings of shaders/tessellation (11 is the search's patch points).
#define TESSELLATION_MESH_VERTICES_BINDING 0
#define TESSELLATION_SEARCH_STATISTICS_BINDING 2
#define TESSELLATION_WORKING_BINDING 3
#define TESSELLATION_SPLITS_BINDING 4
#define TESSELLATION_TOTALS_BINDING 5
#define TESSELLATION_MESH_INDICES_BINDING 6
#define TESSELLATION_REQUESTS_BINDING 7
#define TESSELLATION_RUNS_BINDING 8
#define TESSELLATION_FINISHED_BINDING 9
#define TESSELLATION_NEXT_WORKING_BINDING 10
#define TESSELLATION_DRAWS_BINDING 12
// Where the virtual-objects pass reads the finished triangles (virtual-objects-tessellated.vert).
#define VIRTUAL_OBJECTS_TRIANGLES_BINDING 3

// One run's working triangles in a round, [first, first + count) of the working list it reads
// (round 0: of the part's meshes, numbered run after run).
struct RunWork {
  uint first;
  uint count;
};

struct TessellationRun {
  RunWork work[2];       // this round's in work[round % 2], the next round's in the other
  uint requestCount;     // edges whose midpoint this round searches (classify)
  uint searchGroups[3];  // the indirect dispatch over them (tessellation-dispatch)
  uint children;         // triangles the split ones become (decide)
  uint unsplit;          // drawable triangles that split nothing (decide)
  uint childrenPlaced;   // children written so far (emit)
  uint finishedPlaced;   // finished triangles written so far (emit)
  uint childrenBase;     // where this round's children start in the next working list (layout)
  uint finishedBase;     // where its finished triangles start in the finished list (layout)
  uint finishAll;        // 1: nothing splits this round, every working triangle finishes (layout)
  uint drawnFromMesh;    // 1: the run is drawn from its mesh and emits nothing more (layout)
};

// glDrawArraysIndirect's and glDrawElementsIndirect's commands.
struct DrawArraysCommand {
  uint count;
  uint instanceCount;
  uint first;
  uint baseInstance;
};
struct DrawElementsCommand {
  uint count;
  uint instanceCount;
  uint firstIndex;
  uint baseVertex;  // GL reads an int; always 0 here
  uint baseInstance;
};

// What the virtual-objects pass draws of a run: its mesh with its search slots (instanceCount 1
// when nothing of it split, or its triangles found no room), and each round's finished triangles.
struct RunDraws {
  DrawElementsCommand mesh;
  DrawArraysCommand rounds[TESSELLATION_MAX_ROUNDS];
};

// After round 0, whose triangles are each run's mesh, a round runs each kernel once over all the
// part's runs: their triangles fill [0, triangles) of the working list, run after run.
struct PartWork {
  uint triangles;
  uint groups[3];  // the indirect dispatch over them
};

// The frame's totals, added to part after part; read back once the frame has finished.
struct TessellationTotals {
  PartWork part[2];          // this round's in part[round % 2], the next round's in the other
  uint partRequests;         // edges whose midpoint this round searches, every run of the part
  uint partSearchGroups[3];  // the indirect dispatch over them
  uint finished;        // triangles in the finished list
  uint partBudget;      // the current part may fill the finished list up to here
  uint capped;          // 1: a list reached the cap and splitting stopped early
  uint neededWorking;   // a round's children past the working lists' room (0: they fitted)
  uint neededFinished;  // finished triangles past the finished list's room (0: they fitted)
  uint meshTriangles;   // triangles of runs drawn from their meshes after round 0's decision
  uint trianglesPerRound[TESSELLATION_MAX_ROUNDS];  // working triangles entering each round
};

#ifdef __cplusplus
static_assert(sizeof(RunWork) == 8 && sizeof(TessellationRun) == 64, "std430 layout of TessellationRun");
static_assert(sizeof(RunDraws) == 20 + 16 * TESSELLATION_MAX_ROUNDS, "std430 layout of RunDraws");
}  // namespace specula::passes::gpu
#endif
