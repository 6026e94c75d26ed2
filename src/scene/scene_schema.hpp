// The keys a scene file may hold, as a tree made of their declarations (scene_keys.cpp), and the
// names its enumerations are written with.
// The loader checks documents and `--set` overrides against this tree; the writer uses the
// same names, so that what it writes reads back.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/scene.hpp"

namespace sph::scene {

// One key of the schema. An object lists its keys; an array has a single child, named "[]",
// that describes every element.
struct KeySchema {
  enum class Shape { Value, Object, Array };

  std::string name;
  Shape shape = Shape::Value;
  std::vector<KeySchema> children;
  bool required = false;  // no default: a scene must give it

  const KeySchema* find(const std::string& key) const;
  // A key the loader reads must be in the schema: a miss here is a bug, not bad input.
  const KeySchema& child(const std::string& key) const;
  const KeySchema& element() const { return children.at(0); }
};

const KeySchema& sceneSchema();

// Dotted key paths as messages show them: `fluid.blocks[1].max`.
std::string joinKey(const std::string& parent, const std::string& key);
std::string joinIndex(const std::string& parent, std::size_t index);
// Whether `inner` is `outer` or a key below it (`fluid.blocks[0].max` is within `fluid`).
bool keyWithin(const std::string& inner, const std::string& outer);

// The known key at `level` nearest to `key` by edit distance, if it is close enough to be
// a likely typo.
std::optional<std::string> nearestKey(const std::string& key, const KeySchema& level);

// "unknown key fluid.viscosty (did you mean fluid.viscosity?)", or the list of known keys
// when none is close.
std::string unknownKeyText(const std::string& parentPath, const std::string& key,
                           const KeySchema& level);

template <class Enum>
struct NamedValue {
  const char* name;
  Enum value;
};

inline constexpr NamedValue<OutsidePolicy> kOutsideNames[] = {{"remove", OutsidePolicy::Remove},
                                                              {"clamp", OutsidePolicy::Clamp}};
inline constexpr NamedValue<KernelKind> kKernelNames[] = {{"muller", KernelKind::Muller},
                                                          {"cubic_spline", KernelKind::CubicSpline},
                                                          {"wendland_c2", KernelKind::WendlandC2}};
inline constexpr NamedValue<EquationOfState> kEosNames[] = {{"linear", EquationOfState::Linear},
                                                            {"ratio", EquationOfState::Ratio},
                                                            {"tait", EquationOfState::Tait}};
inline constexpr NamedValue<PressureForm> kPressureFormNames[] = {
    {"paper", PressureForm::Paper}, {"symmetric", PressureForm::Symmetric}};
inline constexpr NamedValue<DensityModel> kDensityModelNames[] = {
    {"summation", DensityModel::Summation}, {"continuity", DensityModel::Continuity}};
inline constexpr NamedValue<FluidSolver> kSolverNames[] = {
    {"wcsph", FluidSolver::Wcsph}, {"dfsph", FluidSolver::Dfsph}, {"pbf", FluidSolver::Pbf}};
inline constexpr NamedValue<ObjectEngineKind> kObjectEngineNames[] = {
    {"builtin", ObjectEngineKind::Builtin}, {"bullet", ObjectEngineKind::Bullet}};
inline constexpr NamedValue<ObjectCoupling> kCouplingNames[] = {
    {"contact", ObjectCoupling::Contact}, {"boundary", ObjectCoupling::Boundary}};
inline constexpr NamedValue<ViscosityModel> kViscosityNames[] = {
    {"muller", ViscosityModel::Muller}, {"artificial", ViscosityModel::Artificial}};
inline constexpr NamedValue<FluidLook> kLookNames[] = {{"liquid", FluidLook::Liquid},
                                                       {"particles", FluidLook::Particles}};
inline constexpr NamedValue<FrameFormat> kFormatNames[] = {{"vtp", FrameFormat::Vtp},
                                                           {"ply", FrameFormat::Ply},
                                                           {"csv", FrameFormat::Csv},
                                                           {"none", FrameFormat::None}};
inline constexpr NamedValue<WallKind> kWallKindNames[] = {
    {"tank", WallKind::Tank},         {"box", WallKind::Box},     {"sphere", WallKind::Sphere},
    {"cylinder", WallKind::Cylinder}, {"plane", WallKind::Plane}, {"mesh", WallKind::Mesh}};
inline constexpr NamedValue<FluidSide> kFluidSideNames[] = {{"outside", FluidSide::Outside},
                                                            {"inside", FluidSide::Inside}};

inline constexpr NamedValue<ProbeKind> kProbeKindNames[] = {
    {"point", ProbeKind::Point}, {"level", ProbeKind::Level}, {"force", ProbeKind::Force}};

inline constexpr NamedValue<EmitterShape> kEmitterShapeNames[] = {
    {"disc", EmitterShape::Disc}, {"rectangle", EmitterShape::Rectangle}};

inline constexpr NamedValue<ObjectMotion> kMotionNames[] = {
    {"rigid", ObjectMotion::Rigid},
    {"deformable", ObjectMotion::Deformable},
    {"kinematic", ObjectMotion::Kinematic}};
inline constexpr NamedValue<DeformableModel> kDeformableModelNames[] = {
    {"springs", DeformableModel::Springs}, {"xpbd", DeformableModel::Xpbd}};
inline constexpr NamedValue<ShapeKind> kShapeNames[] = {{"box", ShapeKind::Box},
                                                        {"sphere", ShapeKind::Sphere},
                                                        {"capsule", ShapeKind::Capsule},
                                                        {"tube", ShapeKind::Tube},
                                                        {"mesh", ShapeKind::Mesh}};

template <class Enum, std::size_t N>
const char* nameOf(Enum value, const NamedValue<Enum> (&names)[N]) {
  for (const auto& named : names) {
    if (named.value == value) return named.name;
  }
  throw std::logic_error("scene enumeration value without a name");
}

}  // namespace sph::scene
