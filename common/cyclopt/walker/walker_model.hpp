#pragma once
// The constants of one walker scene (Pinocchio-style Model): segment parameters, foot, problem
// constants, and the mass distribution derived from them (seed 001 section 5.1).
//
// Mass distribution. Every body b (torso T, thighs O1/O2, shanks U1/U2, feet F1/F2) has its centre
// of mass at r_b = r_A1 + sum_j L_bj e(phi_j), a fixed linear combination of the segment direction
// vectors e(phi) = [sin phi; cos phi] measured from the stance ankle A1 (derived from eq. 5.3 and
// the dimensions of Fig. 5.1b). With a rolling stance foot, r_A1 itself moves with the stance foot
// angle (eq. 5.10) and enters as one more "slot" whose offset is 1 for every body. Velocities are
// then v_b = sum_s L_bs w_s u_s with slot rates u = S q_dot, and the kinetic energy is
//   E_kin = 1/2 sum_{s,t} G_st (w_s . w_t) u_s u_t + 1/2 sum_j J_j u_j^2,   G_st = sum_b m_b L_bs L_bt,
// which gives the mass matrix, the zero dynamics (5.73) and the inverse dynamics (5.35) in O(slots^2)
// (stance_dynamics.hpp). A point-foot scene (Table D.1) has five segments and no rolling slot.

#include "cyclopt/foot/foot_parameters.hpp"
#include "cyclopt/foot/foot_profile.hpp"
#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/walker/foot_density.hpp"
#include "cyclopt/walker/segment_parameters.hpp"

#include <Eigen/Core>

namespace cyclopt::walker {

inline constexpr int kMaxSegments = 7;          // T, O1, O2, U1, U2, F1, F2
inline constexpr int kMaxSlots = kMaxSegments + 1;  // + the rolling stance ankle
inline constexpr int kMaxJoints = 6;            // H1, H2, K1, K2, A1, A2
inline constexpr int kMaxCoordinates = kMaxJoints + 1;  // q_s = [theta; q_b]

// Segment indices (point-foot scenes use the first five).
enum Segment { seg_T = 0, seg_O1, seg_O2, seg_U1, seg_U2, seg_F1, seg_F2 };
// Joint indices into q_b (eq. 5.3): hips, knees, ankles.
enum Joint { joint_H1 = 0, joint_H2, joint_K1, joint_K2, joint_A1, joint_A2 };
// "H1" .. "A2" for joint j in [0, kMaxJoints).
inline const char* joint_name(int j) {
  static const char* names[kMaxJoints] = {"H1", "H2", "K1", "K2", "A1", "A2"};
  return names[j];
}

template <class T>
using SlotMatrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSlots, kMaxSlots>;
template <class T>
using SlotVector = Eigen::Matrix<T, Eigen::Dynamic, 1, 0, kMaxSlots, 1>;
template <class T>
using CoordinateVector = Eigen::Matrix<T, Eigen::Dynamic, 1, 0, kMaxCoordinates, 1>;
template <class T>
using JointVector = Eigen::Matrix<T, Eigen::Dynamic, 1, 0, kMaxJoints, 1>;
// Maps q_s = [theta; q_b] to slot angles (rows: slots, columns: coordinates); constant.
using SlotMap = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSlots, kMaxCoordinates>;
// Offsets of named points (hip, knees, swing ankle) from the stance ankle, per segment.
template <class T>
using SegmentOffsets = Eigen::Matrix<T, 1, Eigen::Dynamic, Eigen::RowMajor, 1, kMaxSegments>;

template <class T>
struct WalkerModel {
  foot::FootModel foot_model = foot::FootModel::point;
  foot::FootParameters<T> foot_parameters;  // p_HM / p_HMT (empty for point feet)
  foot::FootProfile<T> foot;          // F of eq. 3.19 / 3.22, evaluated at theta_F - theta_F,0 (5.4)
  T foot_zero_angle = T(kFootZeroAngle);  // theta_F,0
  FootDensity<T> foot_density;        // with rho: m_F, r_F, J_F, theta_F,0 follow the geometry (10.2)
  SegmentParameters<T> segments{};    // p_mech
  WalkingConstants constants;

  // Derived by make_walker_model():
  int segment_count = 0;  // 7 with feet, 5 with point feet
  int joint_count = 0;    // n_b: 6 with feet, 4 with point feet
  int slot_count = 0;     // segments (+1 rolling slot with feet)
  T total_mass = T(0.0);
  SlotMatrix<T> gram;      // G_st = sum_b m_b L_bs L_bt
  SlotVector<T> first_moment;  // G0_s = sum_b m_b L_bs (gravity and total momentum)
  SlotVector<T> inertia;   // J of the segment rotating with each slot (0 for the rolling slot)
  SlotMap slot_map;        // slot angles = slot_map * q_s (rolling slot = stance foot angle)
  SegmentOffsets<T> hip, knee1, knee2, swing_ankle;  // from the stance ankle

  bool has_feet() const { return foot_model != foot::FootModel::point; }
  int coordinate_count() const { return joint_count + 1; }
  int rolling_slot() const { return segment_count; }  // valid only with feet
};

// Builds the model; segment parameters, foot and theta_F,0 are taken as given (validated by the
// scene spec), except that with a density m_F, r_F, J_F (and theta_F,0 unless fixed) are replaced
// by the foot's mass properties (appendix E). The point-foot model ignores r_F, m_F, J_F and theta_F,0.
template <class T>
WalkerModel<T> make_walker_model(const SegmentParameters<T>& p, foot::FootModel model,
                                 const foot::FootParameters<T>& foot_parameters, const T& foot_zero_angle,
                                 const WalkingConstants& constants = {}, int periodic_terms = 0,
                                 const FootDensity<T>& density = {});

// The seed's reference scenes: Table 5.1 with a foot spec, Table D.1 with point feet. A foot spec
// with a density couples the foot's mass properties to its geometry (section 10.2).
WalkerModel<double> make_walker_model(const foot::FootSpec& foot, const WalkingConstants& constants = {});

// Converts a double model to scalar type T (constants: zero derivative parts).
template <class T>
WalkerModel<T> cast_model(const WalkerModel<double>& m);

}  // namespace cyclopt::walker

#include "cyclopt/walker/walker_model_impl.hpp"
