#pragma once
// A hip torque law M_alpha(x): what the gymnast does, as a function of the state. Simulation, the
// one-step map and its variational equations take any law; each law is written once as a template
// and instantiated for double (values), Dual<1> (alpha''' along the motion) and Dual<4> (the
// Jacobian df/dx of the variational equations) through HipTorqueLawOf (CRTP).
//
//   PiecewiseLinearTorque   the seed's open-loop M_alpha(phi) (hip_torque.hpp)
//   VirtualConstraintTorque part B: enforce alpha = b(phi) (virtual_constraint.hpp)

#include "cyclopt/autodiff/dual.hpp"
#include "cyclopt/giant_swing/equations_of_motion.hpp"
#include "cyclopt/giant_swing/hip_torque.hpp"

namespace cyclopt::giant_swing {

class HipTorqueLaw {
 public:
  virtual ~HipTorqueLaw() = default;
  virtual double operator()(const State<double>& x) const = 0;
  virtual ad::Dual<1> operator()(const State<ad::Dual<1>>& x) const = 0;
  virtual ad::Dual<4> operator()(const State<ad::Dual<4>>& x) const = 0;
};

// Implements the three instantiations from Derived::torque<T>(x).
template <class Derived>
class HipTorqueLawOf : public HipTorqueLaw {
 public:
  double operator()(const State<double>& x) const override { return self().torque(x); }
  ad::Dual<1> operator()(const State<ad::Dual<1>>& x) const override { return self().torque(x); }
  ad::Dual<4> operator()(const State<ad::Dual<4>>& x) const override { return self().torque(x); }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

class PiecewiseLinearTorque : public HipTorqueLawOf<PiecewiseLinearTorque> {
 public:
  explicit PiecewiseLinearTorque(HipTorqueProfile profile) : profile_(std::move(profile)) {}
  template <class T>
  T torque(const State<T>& x) const {
    return hip_torque(profile_, x[0]);
  }

 private:
  HipTorqueProfile profile_;
};

}  // namespace cyclopt::giant_swing
