// The reference ray tracer's mirror images against expectations computed here, independently of the
// tracer: a ray per pixel centre, intersected with the exact mirror quadric (written as a quadratic
// form, not as the tracer's transformed unit sphere) and the checker floor plane, and for mirror
// pixels the ray reflected about the quadric's gradient followed to the floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <memory>

#include "math/Color.h"
#include "reference/RayTracer.h"
#include "scene/Primitives.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"

using namespace specula;

namespace {

// Facts of the checker-sphere specification, restated so the expectation does not read the scene.
constexpr double kFloorHalfExtent = 8.0;
constexpr std::uint8_t kLightByte = 230, kDarkByte = 25;
constexpr int kWidth = 160, kHeight = 120;

struct View {
  glm::dvec3 eye;
  glm::dvec3 target;
  double fovDegrees;
};

// The camera as a float pose holds it, so expectation and tracer start from the same numbers.
View floatView(const glm::dvec3& eye, const glm::dvec3& target, double fovDegrees) {
  return {glm::dvec3(glm::vec3(eye)), glm::dvec3(glm::vec3(target)), static_cast<float>(fovDegrees)};
}

// A mirror ellipsoid: the points p with (p − centre)ᵀ · form · (p − centre) = 1.
struct Quadric {
  glm::dvec3 centre{0.0};
  glm::dmat3 form{1.0};
};

// A perfect mirror quadric above a 16 m checker floor of unit cells (light where the cell indices
// relative to the floor centre sum to an even number), seen from `view`; nothing else.
struct Scenario {
  View view;
  Quadric mirror;
  glm::dvec3 floorCentre;
};

enum class Surface { Background, Light, Dark };

// What a pixel must show: whether its ray meets the mirror, and what it finally sees.
struct Seen {
  bool mirror = false;
  Surface surface = Surface::Background;
  bool operator==(const Seen&) const = default;
};

Surface floorSeen(const glm::dvec3& origin, const glm::dvec3& d, const glm::dvec3& floorCentre) {
  if (d.y >= 0.0) return Surface::Background;
  const glm::dvec3 hit = origin + ((floorCentre.y - origin.y) / d.y) * d - floorCentre;
  if (std::abs(hit.x) > kFloorHalfExtent || std::abs(hit.z) > kFloorHalfExtent) return Surface::Background;
  const long parity = static_cast<long>(std::floor(hit.x)) + static_cast<long>(std::floor(hit.z));
  return parity % 2 == 0 ? Surface::Light : Surface::Dark;
}

// What the ray through image point (x, y) in pixels (row 0 at the top) sees.
Seen trace(const Scenario& scenario, double x, double y) {
  const View& view = scenario.view;
  const glm::dvec3 forward = glm::normalize(view.target - view.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(view.fovDegrees * M_PI / 360.0);
  const double sx = (2.0 * x / kWidth - 1.0) * tanHalf * kWidth / kHeight;
  const double sy = (1.0 - 2.0 * y / kHeight) * tanHalf;
  const glm::dvec3 d = glm::normalize(forward + sx * right + sy * up);
  // (o + t·d)ᵀ·A·(o + t·d) = 1 with o relative to the centre: a·t² + 2b·t + c = 0.
  const Quadric& q = scenario.mirror;
  const glm::dvec3 o = view.eye - q.centre;
  const double a = glm::dot(d, q.form * d), b = glm::dot(d, q.form * o), c = glm::dot(o, q.form * o) - 1.0;
  const double discriminant = b * b - a * c;
  const double t = (-b - std::sqrt(std::max(discriminant, 0.0))) / a;
  if (discriminant <= 0.0 || t <= 0.0) return {false, floorSeen(view.eye, d, scenario.floorCentre)};
  const glm::dvec3 hit = view.eye + t * d;
  const glm::dvec3 n = glm::normalize(q.form * (hit - q.centre));  // the gradient of the quadratic form
  return {true, floorSeen(hit, d - 2.0 * glm::dot(d, n) * n, scenario.floorCentre)};
}

// The pixel centre and the four points half a pixel away; where all agree the pixel is unambiguous.
std::array<Seen, 5> around(const Scenario& scenario, int column, int row) {
  const double cx = column + 0.5, cy = row + 0.5;
  return {trace(scenario, cx, cy), trace(scenario, cx - 0.5, cy), trace(scenario, cx + 0.5, cy),
          trace(scenario, cx, cy - 0.5), trace(scenario, cx, cy + 0.5)};
}

bool unambiguous(const std::array<Seen, 5>& seen) {
  return std::all_of(seen.begin(), seen.end(), [&](const Seen& s) { return s == seen[0]; });
}

// The exact bytes each surface has in a scene.
struct Palette {
  std::array<std::uint8_t, 3> background{0, 0, 0};
  std::array<std::uint8_t, 3> light{kLightByte, kLightByte, kLightByte};
  std::array<std::uint8_t, 3> dark{kDarkByte, kDarkByte, kDarkByte};

  const std::array<std::uint8_t, 3>& operator[](Surface s) const {
    return s == Surface::Light ? light : s == Surface::Dark ? dark : background;
  }
};

bool shows(const reference::ReferenceImage& image, int column, int row, const std::array<std::uint8_t, 3>& rgb) {
  const std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(row) * kWidth + column) * 4];
  return p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2];
}

bool masked(const reference::ReferenceImage& image, int column, int row) {
  return image.mirrorMask[static_cast<std::size_t>(row) * kWidth + column] != 0;
}

// Every unambiguous mirror pixel must show exactly what the exact reflected ray sees. Returns how many
// pixels the mirror covers and how many were checked, so callers can refuse a vacuous pass.
std::pair<int, int> expectExactReflections(const Scenario& scenario, const reference::ReferenceImage& image,
                                           const Palette& palette) {
  int mirror = 0, checked = 0, mismatched = 0;
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const std::array<Seen, 5> seen = around(scenario, column, row);
      mirror += seen[0].mirror;
      if (!seen[0].mirror || !unambiguous(seen)) continue;
      ++checked;
      if (!shows(image, column, row, palette[seen[0].surface]) && ++mismatched <= 10)
        ADD_FAILURE() << "mirror pixel (" << column << ", " << row << ") does not show what the reflected ray sees ("
                      << static_cast<int>(seen[0].surface) << ")";
    }
  EXPECT_EQ(mismatched, 0);
  return {mirror, checked};
}

Result<reference::ReferenceImage> renderFrom(const scene::Scene& s, const View& view) {
  auto tracer = reference::RayTracer::create(std::make_shared<const scene::Scene>(s));
  if (!tracer) return Error{tracer.error()};
  scene::ScenePose pose = scene::ScenePose::at(s, 0.0);
  pose.camera = {glm::vec3(view.eye), glm::vec3(view.target), {0.0f, 1.0f, 0.0f}, static_cast<float>(view.fovDegrees)};
  return (*tracer)->render(pose, {kWidth, kHeight, 1, 0});
}

const Scenario kCheckerSphere{floatView({1.0, 3.0, 3.5}, {0.0, -0.3, 0.0}, 40.0), {}, {0.0, -1.0, 0.0}};

class ReferenceCheckerSphere : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto built = scene::makeBuiltinScene("checker-sphere");
    ASSERT_TRUE(built.has_value());
    built->environment.kind = scene::EnvironmentKind::Colour;  // black past the floor: every pixel has a known byte
    auto tracer = reference::RayTracer::create(std::make_shared<const scene::Scene>(std::move(*built)));
    ASSERT_TRUE(tracer) << tracer.error();
    auto rendered = (*tracer)->render(scene::ScenePose::at((*tracer)->scene(), 0.0), {kWidth, kHeight, 1, 0});
    ASSERT_TRUE(rendered) << rendered.error();
    image_ = std::make_unique<reference::ReferenceImage>(std::move(*rendered));
  }
  static void TearDownTestSuite() { image_.reset(); }

  static std::unique_ptr<reference::ReferenceImage> image_;
};
std::unique_ptr<reference::ReferenceImage> ReferenceCheckerSphere::image_;

TEST_F(ReferenceCheckerSphere, ImageIsOpaqueAndGreyAtTheRequestedSize) {
  ASSERT_NE(image_, nullptr);
  ASSERT_EQ(image_->width, kWidth);
  ASSERT_EQ(image_->height, kHeight);
  ASSERT_EQ(image_->rgba.size(), std::size_t{kWidth} * kHeight * 4);
  ASSERT_EQ(image_->mirrorMask.size(), std::size_t{kWidth} * kHeight);
  for (std::size_t i = 0; i < image_->rgba.size(); i += 4) {
    ASSERT_EQ(image_->rgba[i + 3], 255);
    ASSERT_EQ(image_->rgba[i], image_->rgba[i + 1]);  // every colour in this scene is a grey
    ASSERT_EQ(image_->rgba[i], image_->rgba[i + 2]);
  }
  EXPECT_GE(image_->milliseconds, 0.0);
}

TEST_F(ReferenceCheckerSphere, FloorPixelsMatchRayPlaneExpectationExactly) {
  ASSERT_NE(image_, nullptr);
  const Palette grey;
  int checked = 0, exact = 0, mismatched = 0;
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const std::array<Seen, 5> seen = around(kCheckerSphere, column, row);
      if (std::any_of(seen.begin(), seen.end(), [](const Seen& s) { return s.mirror; })) continue;
      const bool sure = unambiguous(seen);
      // An unambiguous pixel must take the centre's colour; one on an edge either side's.
      const bool matches = sure ? shows(*image_, column, row, grey[seen[0].surface])
                                : std::any_of(seen.begin(), seen.end(), [&](const Seen& s) {
                                    return shows(*image_, column, row, grey[s.surface]);
                                  });
      ++checked;
      exact += sure;
      if (!matches && ++mismatched <= 10) ADD_FAILURE() << "floor pixel (" << column << ", " << row << ") is wrong";
    }
  EXPECT_EQ(mismatched, 0);
  EXPECT_GT(checked, kWidth * kHeight * 6 / 10);  // not vacuous: most of the image is floor or background
  EXPECT_GT(exact, checked * 8 / 10);
}

TEST_F(ReferenceCheckerSphere, SpherePixelsShowTheFloorCellTheExactReflectedRayHits) {
  ASSERT_NE(image_, nullptr);
  const auto [sphere, checked] = expectExactReflections(kCheckerSphere, *image_, Palette{});
  EXPECT_GT(sphere, 2000);  // the sphere covers a good part of the image
  EXPECT_GT(checked, sphere * 6 / 10);
}

TEST_F(ReferenceCheckerSphere, MirrorMaskIsTheAnalyticSphereExceptAtTheSilhouette) {
  ASSERT_NE(image_, nullptr);
  int inside = 0, wrong = 0;
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const std::array<Seen, 5> seen = around(kCheckerSphere, column, row);
      const bool silhouette =
          std::any_of(seen.begin(), seen.end(), [&](const Seen& s) { return s.mirror != seen[0].mirror; });
      inside += masked(*image_, column, row);
      if (!silhouette && masked(*image_, column, row) != seen[0].mirror && ++wrong <= 10)
        ADD_FAILURE() << "mask at (" << column << ", " << row << ") is " << masked(*image_, column, row);
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(inside, 2000);
}

// A perfect mirror ellipsoid or sphere whose surface colour (unlit) is `mirrorColor`, over the checker
// floor, with a blue background. The mesh is a coarse unit sphere: only the analytic shape is right.
scene::Scene mirrorOverFloor(const math::Transform& mirrorPlacement, const scene::AnalyticShape& shape,
                             const glm::vec3& floorCentre, const glm::vec3& mirrorColor) {
  scene::Scene s;
  s.ambient = glm::vec3(0.0f);
  s.background = glm::vec3(0.0f, 0.0f, 1.0f);
  scene::Material floor;
  floor.unlit = true;
  floor.baseColor = math::srgbToLinear(glm::vec3(kLightByte / 255.0f));
  floor.checker = scene::Checker{math::srgbToLinear(glm::vec3(kDarkByte / 255.0f)), 1.0f};
  scene::Material mirror;
  mirror.unlit = true;
  mirror.baseColor = mirrorColor;
  mirror.reflectivity = 1.0f;
  s.materials = {floor, mirror};
  s.meshes = {scene::primitives::grid("floor", 16.0f, 16.0f, 16, 16),
              scene::primitives::uvSphere("coarse", 1.0f, 12, 6)};
  scene::SceneObject floorObject;
  floorObject.name = "floor";
  floorObject.transform.translation = floorCentre;
  scene::SceneObject mirrorObject;
  mirrorObject.name = "mirror";
  mirrorObject.mesh = 1;
  mirrorObject.material = 1;
  mirrorObject.transform = mirrorPlacement;
  mirrorObject.mirror.emplace().analytic = shape;
  s.objects = {floorObject, mirrorObject};
  return s;
}

constexpr Palette kBlueBackground{{0, 0, 255}};

TEST(ReferenceSelfIntersection, MirrorSphereNeverShowsItsOwnColourAtGrazingOrFarViews) {
  struct Case {
    const char* name;
    glm::dvec3 centre;
    glm::dvec3 eyeOffset;  // from the sphere centre
    double fovDegrees;
  };
  // Every view shows the silhouette, where reflected rays graze the surface they leave.
  const Case cases[] = {
      {"near, straight on", {0.0, 0.0, 0.0}, {0.0, 0.0, 3.0}, 60.0},
      {"near, grazing from floor level", {0.0, 0.0, 0.0}, {0.0, -0.9, 2.5}, 70.0},
      {"far eye", {0.0, 0.0, 0.0}, {0.0, 300.0, 2000.0}, 0.08},
      {"away from the world origin", {300.0, 0.0, -200.0}, {0.3, 0.5, 3.0}, 60.0},
      {"far eye, away from the world origin", {300.0, 0.0, -200.0}, {0.0, 1000.0, 1500.0}, 0.1},
  };
  // Magenta, which nothing else has: one bounce that met its own sphere again would paint it.
  const glm::vec3 magenta(1.0f, 0.0f, 1.0f);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const glm::vec3 centre(c.centre), floorCentre = centre - glm::vec3(0.0f, 1.0f, 0.0f);
    const scene::AnalyticShape unitSphere{scene::AnalyticShape::Kind::Sphere, glm::vec3(0.0f), glm::vec3(1.0f)};
    const Scenario scenario{floatView(c.centre + c.eyeOffset, c.centre, c.fovDegrees),
                            {c.centre, glm::dmat3(1.0)},
                            glm::dvec3(floorCentre)};
    auto image = renderFrom(mirrorOverFloor(math::Transform{centre}, unitSphere, floorCentre, magenta), scenario.view);
    ASSERT_TRUE(image) << image.error();
    int ownColour = 0;
    for (int row = 0; row < kHeight; ++row)
      for (int column = 0; column < kWidth; ++column)
        if (shows(*image, column, row, {255, 0, 255}) && ++ownColour <= 5)
          ADD_FAILURE() << "pixel (" << column << ", " << row << ") shows the mirror's own colour";
    EXPECT_EQ(ownColour, 0);
    const auto [sphere, checked] = expectExactReflections(scenario, *image, kBlueBackground);
    EXPECT_GT(sphere, kWidth * kHeight / 10);
    EXPECT_GT(checked, sphere / 2);
  }
}

TEST(ReferenceEllipsoid, ReflectsAboutTheExactQuadricNotTheCoarseMesh) {
  // An off-centre ellipsoid in an object turned about a slanted axis and scaled unevenly.
  const scene::AnalyticShape shape{scene::AnalyticShape::Kind::Ellipsoid, {0.1f, 0.2f, 0.0f}, {1.2f, 0.6f, 0.9f}};
  const math::Transform placement{{0.3f, 0.4f, -0.2f},
                                  glm::angleAxis(glm::radians(30.0f), glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f))),
                                  {1.1f, 0.9f, 1.0f}};
  const glm::vec3 floorCentre(0.0f, -2.0f, 0.0f);
  // The quadric in world space: p = centre + L·u for unit u, so (p − centre)ᵀ·L⁻ᵀ·L⁻¹·(p − centre) = 1.
  const glm::dmat3 rotation = glm::mat3_cast(glm::dquat(placement.rotation));
  const glm::dmat3 linear = rotation * glm::dmat3(glm::scale(glm::dmat4(1.0), glm::dvec3(placement.scale))) *
                            glm::dmat3(glm::scale(glm::dmat4(1.0), glm::dvec3(shape.radii)));
  const glm::dvec3 centre =
      glm::dvec3(placement.translation) + rotation * (glm::dvec3(placement.scale) * glm::dvec3(shape.center));
  const glm::dmat3 inverse = glm::inverse(linear);
  const Scenario scenario{floatView({2.5, 2.0, 4.0}, {0.3, 0.3, -0.2}, 45.0),
                          {centre, glm::transpose(inverse) * inverse},
                          glm::dvec3(floorCentre)};

  auto image = renderFrom(mirrorOverFloor(placement, shape, floorCentre, {1.0f, 0.0f, 1.0f}), scenario.view);
  ASSERT_TRUE(image) << image.error();
  const auto [mirror, checked] = expectExactReflections(scenario, *image, kBlueBackground);
  EXPECT_GT(mirror, kWidth * kHeight / 10);
  EXPECT_GT(checked, mirror / 2);
  int wrongMask = 0;
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const std::array<Seen, 5> seen = around(scenario, column, row);
      if (unambiguous(seen) && masked(*image, column, row) != seen[0].mirror) ++wrongMask;
    }
  EXPECT_EQ(wrongMask, 0);
}

}  // namespace
