#pragma once
// The 4D beating heart (SPEC S3, paper 2.2): a sequence of closed surface meshes with one
// topology, one per cardiac phase, played back periodically with C1 interpolation. The default
// is procedural: left and right ventricles as closed surfaces whose volumes follow a
// physiological curve (ejection fraction, systole share of the cycle) with longitudinal
// shortening and twist; a series loaded from files takes the keyframes' place.
#include <cstdint>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace imasim::tissue {

struct HeartParams {
  Vec3 centre = Vec3(Real(0.005), Real(-0.05), Real(0.09));            // LV centre (unit: m)
  Vec3 long_axis = Vec3(Real(0.3), Real(-0.3), Real(1)).normalized();  // base -> apex
  Vec3 lateral = Vec3::UnitX();  // towards the RV side (made orthogonal to the long axis)
  Real lv_length = Real(0.085);  // base-apex at end-diastole (unit: m)
  Real lv_radius = Real(0.026);  // (unit: m)
  Real rv_length = Real(0.075), rv_radius = Real(0.024);
  Real rv_offset = Real(0.022);               // RV centre from LV centre along `lateral` (m)
  Real ejection_fraction = Real(0.6);         // (EDV - ESV) / EDV
  Real systole_fraction = Real(0.35);         // share of the cycle spent ejecting
  Real longitudinal_shortening = Real(0.12);  // base-apex shortening at end-systole
  Real twist = Real(0.2);                     // apex rotation against the base at end-systole (rad)
  std::uint32_t phases = 11;                  // keyframes per cycle (the paper's 11)
  std::uint32_t rings = 12, segments = 18;    // surface resolution per ventricle
};

// Keyframes with one topology; keyframe k is the shape at cycle fraction k / phases.
struct HeartModel {
  geometry::TriangleMesh topology;             // triangles + the end-diastole vertices
  std::vector<std::vector<Vec3>> keyframes;    // [phase][vertex]
  std::vector<std::uint32_t> component_start;  // vertex ranges of LV, RV (and end)
  std::vector<std::uint32_t> component_triangle_start;
};

HeartModel make_procedural_heart(const HeartParams& params);

// The cardiac cycle in the R-R convention of cardiac CT (SPEC S3 reading): cycle fraction t = 0
// is the R wave (end-diastole), then ejection, rapid filling, diastasis, atrial contraction.
// Diastole, [s, 1] with s = systole_fraction, is divided in shares of its length D = 1 - s, as
// physiology texts divide it in thirds (Guyton & Hall, Textbook of Medical Physiology, ch. 9:
// rapid filling in the first third, little flow in the middle third (diastasis), the atria's
// contraction in the last third adding about 20 % of the filling):
inline constexpr Real kRapidFillingEnd = Real(0.4);  // rapid filling over [s, s + 0.4 D]
inline constexpr Real kAtrialStart = Real(0.7);      // diastasis until s + 0.7 D
inline constexpr Real kAtrialEnd = Real(0.92);       // atrial contraction until s + 0.92 D
// Shares of the stroke volume refilled in each stage: rapid filling 75 %, diastasis 3 % (slow
// inflow, nearly flat), the atrial kick the remaining 22 % (20-25 % in healthy adults).
inline constexpr Real kRapidFillingShare = Real(0.75);
inline constexpr Real kDiastasisShare = Real(0.03);
inline constexpr Real kAtrialShare = 1 - kRapidFillingShare - kDiastasisShare;

// Where each stage ends, as cycle fractions (at the defaults, s = 0.35: rapid filling to 0.61,
// diastasis to 0.805, atrial contraction to 0.948; the static phase 0.7 is mid-diastasis).
struct CardiacPhases {
  Real end_systole = 0, end_rapid_filling = 0, atrial_start = 0, atrial_end = 0;
};
CardiacPhases cardiac_phases(const HeartParams& params);

// The volume curve of the procedural heart as a fraction of end-diastolic volume, t in [0, 1):
// a cosine fall to 1 - EF over [0, s] (ejection); cubic Hermite rise by 75 % of EF to the end of
// rapid filling; linear by 3 % through diastasis; cubic Hermite by the remaining 22 % over the
// atrial contraction; 1 until the next R wave. Each piece meets the next with the same value
// and slope (C1, periodic), and the volume never falls in diastole.
Real heart_volume_fraction(const HeartParams& params, Real t);

// Periodic Catmull-Rom interpolation of the keyframes at cycle fraction t (any real t; C1 in t,
// passes through every keyframe). Writes vertex positions into `out` (sized to the vertices).
void interpolate_heart(const HeartModel& heart, Real t, std::vector<Vec3>& out);

// The derivative of interpolate_heart's `vertex` with respect to the cycle fraction t (unit: m
// per cycle); continuous in t, as the interpolation is C1.
Vec3 heart_vertex_rate(const HeartModel& heart, Real t, std::uint32_t vertex);

// Enclosed volume of component c (LV 0, RV 1) of a heart shape (unit: m^3).
Real component_volume(const HeartModel& heart, const std::vector<Vec3>& positions,
                      std::uint32_t component);

// Playback: the beating heart at a heart rate, or frozen at one phase (the paper's static group,
// at 70 % of the cycle by default).
struct HeartPlayback {
  Real heart_rate_bpm = 75;
  bool beating = true;
  Real static_phase = Real(0.7);

  // Cycle fraction in [0, 1): static_phase + time * rate when beating (so both modes start from
  // the same shape), static_phase when not.
  Real phase_at(double time_s) const;
  // d(phase)/d(time): heart_rate_bpm / 60 when beating, 0 when not (unit: 1/s).
  Real cycles_per_second() const;
};

}  // namespace imasim::tissue
