// Per-frame search totals (std430 twin of passes::SearchStatistics), added to by every search.

layout(std430, binding = 2) buffer SearchStatistics {
  uint searched, hidden, unsolved, coldStarts;
  uint totalSteps, maxSteps, warmSteps, coldSteps;
  uint enlarged, inNoCone;
};

void countSearch(int steps, int flags) {
  atomicAdd(searched, 1u);
  atomicAdd(totalSteps, uint(steps));
  atomicMax(maxSteps, uint(steps));
  if ((flags & kReflectionHidden) != 0) atomicAdd(hidden, 1u);
  if ((flags & kReflectionUnsolved) != 0) atomicAdd(unsolved, 1u);
  if ((flags & kReflectionEnlarged) != 0) atomicAdd(enlarged, 1u);
  if ((flags & kReflectionInNoCone) != 0) atomicAdd(inNoCone, 1u);
  if ((flags & kReflectionColdStart) != 0) {
    atomicAdd(coldStarts, 1u);
    atomicAdd(coldSteps, uint(steps));
  } else {
    atomicAdd(warmSteps, uint(steps));
  }
}
