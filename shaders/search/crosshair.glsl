// Estalella et al.'s (2006) crosshair search: hill-climb N·B over the mirror's G-buffer in 3×3
// windows from a seed texel when it is on the mirror, else coarse-to-fine down the G-buffer pyramid.
#include "search/core.glsl"

uniform int coarseLevel;       // pyramid level scanned exhaustively on a cold start
uniform ivec4 coarseRect;      // the texels of that level the mirror covers: low x, y, high x, y (exclusive)
uniform int maxWalkSteps;

// Moves to the best of the 3×3 window until the centre is best; each window examined is a step.
ivec2 climb(ivec2 texel, int level, int stepLimit, inout int steps, out float value) {
  value = objectiveAt(texel, level);
  for (int i = 0; i < stepLimit; ++i) {
    ++steps;
    ivec2 next = texel;
    float nextValue = value;
    for (int k = 0; k < 8; ++k) {
      float candidate = objectiveAt(texel + kNeighbours[k], level);
      if (candidate > nextValue) {
        nextValue = candidate;
        next = texel + kNeighbours[k];
      }
    }
    if (next == texel) break;
    texel = next;
    value = nextValue;
  }
  return texel;
}

// Exhaustive scan of the mirror's texels at the coarse level, keeping the best few coarse texels
// that are not neighbours (a part whose normals wrap, like a bowl's outside with its rim, has more
// than one local best: averaged coarse normals can rank the wrong one first), then one climb per
// finer level from each; the best at level 0 wins. The level is the one where the mirror spans at
// most 8 texels (16 on other mirrors than closed convex ones), so a small mirror is still seen in
// parts whose normals differ.
const int kMaxColdCandidates = 3;
uniform int coldCandidates;  // 1 on a closed convex mirror (one best), kMaxColdCandidates otherwise

ivec2 coldSearch(inout int steps, out float value) {
  ivec2 candidate[kMaxColdCandidates];
  float candidateValue[kMaxColdCandidates];
  for (int k = 0; k < kMaxColdCandidates; ++k) {
    candidate[k] = coarseRect.xy;
    candidateValue[k] = kInvalid;
  }
  for (int y = coarseRect.y; y < coarseRect.w; ++y) {
    for (int x = coarseRect.x; x < coarseRect.z; ++x) {
      float v = objectiveAt(ivec2(x, y), coarseLevel);
      if (v <= candidateValue[coldCandidates - 1]) continue;
      // Replace a kept neighbour it beats, else the worst kept; then restore the order.
      int slot = coldCandidates - 1;
      bool beaten = false;
      for (int k = 0; k < coldCandidates; ++k) {
        ivec2 apart = abs(candidate[k] - ivec2(x, y));
        if (candidateValue[k] > kInvalid && max(apart.x, apart.y) <= 2) {
          slot = k;
          beaten = v <= candidateValue[k];
          break;
        }
      }
      if (beaten) continue;
      candidate[slot] = ivec2(x, y);
      candidateValue[slot] = v;
      for (int k = slot; k > 0 && candidateValue[k] > candidateValue[k - 1]; --k) {
        ivec2 t = candidate[k];
        candidate[k] = candidate[k - 1];
        candidate[k - 1] = t;
        float tv = candidateValue[k];
        candidateValue[k] = candidateValue[k - 1];
        candidateValue[k - 1] = tv;
      }
    }
  }
  steps += ((coarseRect.z - coarseRect.x) * (coarseRect.w - coarseRect.y) + 8) / 9;  // in 3×3 windows, like climb steps
  ivec2 best = candidate[0];
  value = kInvalid;
  for (int k = 0; k < coldCandidates; ++k) {
    if (candidateValue[k] <= kInvalid) break;
    ivec2 texel = candidate[k];
    float reached = candidateValue[k];
    for (int level = coarseLevel - 1; level >= 0; --level) texel = climb(texel * 2, level, maxWalkSteps, steps, reached);
    if (reached > value) {
      value = reached;
      best = texel;
    }
  }
  return best;
}
