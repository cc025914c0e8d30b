// SPDX-License-Identifier: Apache-2.0
// Denavit-Hartenberg table of the 6-axis arm (RSM-10: TCP speed from forward kinematics).
#pragma once

#include <array>

#include "safestate/joint_vector.hpp"

namespace safestate {

/// One row of a *classic* (standard, distal) DH table:
///   ^{i-1}T_i = Rot_z(theta_i + theta_offset) · Trans_z(d) · Trans_x(a) · Rot_x(alpha)
/// Lengths in metres, angles in radians.
struct DhRow {
  double a_m;
  double alpha_rad;
  double d_m;
  double theta_offset_rad;
};

using DhTable = std::array<DhRow, kAxisCount>;

namespace detail {
inline constexpr double kHalfPi = 1.57079632679489661923;  // pi / 2
}  // namespace detail

/// Universal Robots UR5 (CB3, "serie 3"), standard DH parameters as published by Universal
/// Robots:
///   - Universal Robots support article "Parameters for calculations of kinematics and
///     dynamics" (FAQ 45257),
///     https://www.universal-robots.com/how-tos-and-faqs/faq/ur-faq/parameters-for-calculations-of-kinematics-and-dynamics-45257/
///   - UR CB3 manual, appendix "Robot DH Parameter", Table "Denavit-Hartenberg parameters
///     for the UR5 serie 3".
///
///   joint | theta [rad] | a [m]    | d [m]    | alpha [rad]
///   ------+-------------+----------+----------+------------
///     1   | 0           |  0       | 0.089159 |  pi/2
///     2   | 0           | -0.42500 | 0        |  0
///     3   | 0           | -0.39225 | 0        |  0
///     4   | 0           |  0       | 0.10915  |  pi/2
///     5   | 0           |  0       | 0.09465  | -pi/2
///     6   | 0           |  0       | 0.0823   |  0
///
/// The last frame is the tool flange (the TCP with no tool mounted).
inline constexpr DhTable kUr5DhTable{{
    //  a_m       alpha_rad          d_m       theta_offset_rad
    {0.0, detail::kHalfPi, 0.089159, 0.0},
    {-0.425, 0.0, 0.0, 0.0},
    {-0.39225, 0.0, 0.0, 0.0},
    {0.0, detail::kHalfPi, 0.10915, 0.0},
    {0.0, -detail::kHalfPi, 0.09465, 0.0},
    {0.0, 0.0, 0.0823, 0.0},
}};

}  // namespace safestate
