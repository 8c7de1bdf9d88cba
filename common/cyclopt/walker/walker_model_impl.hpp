#pragma once
// Template definitions of walker_model.hpp.

namespace cyclopt::walker {

namespace detail {

// Coefficients of q_s = [theta; H1; H2; K1; K2; A1; A2] in each absolute segment angle:
// eq. (5.3) combined with the phase variable theta = theta_T + theta_H1 + theta_K1/2 (5.48).
inline constexpr double kSegmentAngles[kMaxSegments][kMaxCoordinates] = {
    {1, -1, 0, -0.5, 0, 0, 0},  // T  = theta - H1 - K1/2
    {1, 0, 0, -0.5, 0, 0, 0},   // O1 = T + H1
    {1, -1, 1, -0.5, 0, 0, 0},  // O2 = T + H2
    {1, 0, 0, 0.5, 0, 0, 0},    // U1 = O1 + K1
    {1, -1, 1, -0.5, 1, 0, 0},  // U2 = O2 + K2
    {1, 0, 0, 0.5, 0, 1, 0},    // F1 = U1 + A1
    {1, -1, 1, -0.5, 1, 0, 1},  // F2 = U2 + A2
};

}  // namespace detail

template <class T>
WalkerModel<T> make_walker_model(const SegmentParameters<T>& segments, foot::FootModel model,
                                 const foot::FootParameters<T>& foot_parameters, const T& foot_zero_angle,
                                 const WalkingConstants& constants, int periodic_terms,
                                 const FootDensity<T>& density) {
  WalkerModel<T> m;
  m.foot_model = model;
  m.foot_parameters = foot_parameters;
  m.foot = foot::make_profile<T>(model, foot_parameters, periodic_terms);
  m.foot_zero_angle = foot_zero_angle;
  m.foot_density = density;
  m.segments = segments;
  apply_foot_density(density, m.foot, m.segments, m.foot_zero_angle);
  const SegmentParameters<T>& p = m.segments;  // with a density: the coupled values
  m.constants = constants;
  const bool feet = model != foot::FootModel::point;
  m.segment_count = feet ? 7 : 5;
  m.joint_count = feet ? 6 : 4;
  m.slot_count = m.segment_count + (feet ? 1 : 0);
  const int ns = m.segment_count, nq = m.joint_count + 1;

  // Body CoM offsets L (rows: bodies = segments, columns: segments) from the stance ankle.
  SlotMatrix<T> L = SlotMatrix<T>::Zero(ns, ns);
  const T lO = p[l_O], lU = p[l_U];
  L(seg_T, seg_T) = p[r_T];
  L(seg_T, seg_O1) = -lO;
  L(seg_T, seg_U1) = -lU;
  L(seg_O1, seg_O1) = -(lO - p[r_O]);
  L(seg_O1, seg_U1) = -lU;
  L(seg_O2, seg_O2) = p[r_O];
  L(seg_O2, seg_O1) = -lO;
  L(seg_O2, seg_U1) = -lU;
  L(seg_U1, seg_U1) = -(lU - p[r_U]);
  L(seg_U2, seg_U2) = p[r_U];
  L(seg_U2, seg_O2) = lO;
  L(seg_U2, seg_O1) = -lO;
  L(seg_U2, seg_U1) = -lU;
  SlotVector<T> mass(ns), inertia(m.slot_count);
  mass.head(5) << p[m_T], p[m_O], p[m_O], p[m_U], p[m_U];
  inertia.setZero();
  inertia.head(5) << p[J_T], p[J_O], p[J_O], p[J_U], p[J_U];
  if (feet) {
    L(seg_F1, seg_F1) = p[r_F];
    L.row(seg_F2) = L.row(seg_U2);
    L(seg_F2, seg_U2) = lU;
    L(seg_F2, seg_F2) = p[r_F];
    mass.tail(2).setConstant(p[m_F]);
    inertia(seg_F1) = p[J_F];
    inertia(seg_F2) = p[J_F];
  }
  m.total_mass = mass.sum();

  // Gram matrix and first moments; the rolling slot has offset 1 for every body.
  m.gram = SlotMatrix<T>::Zero(m.slot_count, m.slot_count);
  m.first_moment = SlotVector<T>::Zero(m.slot_count);
  for (int b = 0; b < ns; ++b) {
    SlotVector<T> Lb = SlotVector<T>::Zero(m.slot_count);
    Lb.head(ns) = L.row(b).transpose();
    if (feet) Lb(ns) = T(1.0);
    for (int s = 0; s < m.slot_count; ++s) {
      m.first_moment(s) += mass(b) * Lb(s);
      for (int t = 0; t < m.slot_count; ++t) m.gram(s, t) += mass(b) * Lb(s) * Lb(t);
    }
  }
  m.inertia = inertia;

  m.slot_map = SlotMap::Zero(m.slot_count, nq);
  for (int s = 0; s < ns; ++s)
    for (int c = 0; c < nq; ++c) m.slot_map(s, c) = detail::kSegmentAngles[s][c];
  if (feet) m.slot_map.row(ns) = m.slot_map.row(seg_F1);

  auto offsets = [&](std::initializer_list<std::pair<int, T>> entries) {
    SegmentOffsets<T> r = SegmentOffsets<T>::Zero(ns);
    for (const auto& [s, v] : entries) r(s) = v;
    return r;
  };
  m.hip = offsets({{seg_O1, -lO}, {seg_U1, -lU}});
  m.knee1 = offsets({{seg_U1, -lU}});
  m.knee2 = offsets({{seg_O1, -lO}, {seg_U1, -lU}, {seg_O2, lO}});
  m.swing_ankle = offsets({{seg_O1, -lO}, {seg_U1, -lU}, {seg_O2, lO}, {seg_U2, lU}});
  return m;
}

template <class T>
WalkerModel<T> cast_model(const WalkerModel<double>& d) {
  SegmentParameters<T> p;
  for (int i = 0; i < segment_parameter_count; ++i) p[i] = T(d.segments[i]);
  FootDensity<T> density;
  if (d.foot_density.rho) density.rho = T(*d.foot_density.rho);
  density.zero_angle_from_geometry = d.foot_density.zero_angle_from_geometry;
  return make_walker_model<T>(p, d.foot_model, d.foot_parameters.template cast<T>(), T(d.foot_zero_angle), d.constants,
                              d.foot.periodic_terms, density);
}

}  // namespace cyclopt::walker
