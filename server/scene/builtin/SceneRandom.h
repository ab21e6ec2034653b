#pragma once
// Seeded pseudo-random numbers for scattering scene props, identical on every platform
// (std::mt19937's sequence is standardised; the standard distributions are not, so none is used).
#include <cstdint>
#include <random>

namespace specula::scene::builtin {

class SceneRandom {
 public:
  explicit SceneRandom(std::uint32_t seed) : engine_(seed) {}

  // Uniform in [lo, hi] (hi itself only by rounding).
  float uniform(float lo, float hi);
  // Uniform integer in [0, count).
  std::uint32_t index(std::uint32_t count);

 private:
  std::mt19937 engine_;
};

}  // namespace specula::scene::builtin
