#pragma once
// Which records may become a stored point's values or trajectory (storage::SolutionPoint, the
// only door into the store): each record family's header marks its top-level records,
//
//   template <> inline constexpr bool is_point_values<WalkerPointRecord> = true;
//
// so that a job kind cannot store a value that no record of the contract describes.

namespace cyclopt::records {

template <class T>
inline constexpr bool is_point_values = false;
template <class T>
inline constexpr bool is_point_trajectory = false;

template <class T>
concept PointValues = is_point_values<T>;
template <class T>
concept PointTrajectory = is_point_trajectory<T>;

}  // namespace cyclopt::records
