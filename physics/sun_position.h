// The sun's direction in the sky from the local solar time, the latitude and the day of
// the year: the NOAA Global Monitoring Division's "General Solar Position Calculations"
// (Spencer 1971's Fourier series for the declination, the hour angle from the true solar
// time, the zenith from the spherical law of cosines). CPU only: the loader turns it into
// a directional light's direction, which is all the GPU sees.
//
// Scene axes (DESIGN.md: right-handed, Y up): +X is east, −Z is north (so +Z is south).
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace volgraph::physics {

// Spencer 1971 (Search 2(5), 172), as NOAA gives it: the declination (rad) from the
// fractional year γ = 2π/365 · (day − 1 + (hour − 12)/24); Spencer states a maximum error
// of 0.0006 rad (0.035°) for the year it was fitted to (the equinoxes of other years fall
// up to a day away: the declination moves 0.4° a day then).
inline double solar_declination(int day_of_year, double hour) {
  const double g = 2 * std::numbers::pi / 365 * (day_of_year - 1 + (hour - 12) / 24);
  return 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) - 0.006758 * std::cos(2 * g) +
         0.000907 * std::sin(2 * g) - 0.002697 * std::cos(3 * g) + 0.00148 * std::sin(3 * g);
}

// The hour angle (rad) at true (apparent) solar time `solar_hours` (0 … 24): 15° an hour,
// 0 at solar noon, negative in the morning (NOAA: ha = tst/4 − 180°).
inline double solar_hour_angle(double solar_hours) { return (solar_hours - 12) * std::numbers::pi / 12; }

// The unit vector toward the sun in scene axes (+X east, +Y up, −Z north) at true solar
// time `solar_hours`, latitude `latitude_deg` (north positive) and day `day_of_year`
// (1 … 366). Its y is the cosine of the solar zenith (NOAA: sin φ sin δ + cos φ cos δ cos h);
// east = −cos δ sin h, north = cos φ sin δ − sin φ cos δ cos h (the same sphere's
// horizontal components). The local solar time stands in for NOAA's UTC hour in γ (the
// declination moves at most 0.2° in the half day that can make).
inline std::array<double, 3> sun_direction(double solar_hours, double latitude_deg, int day_of_year) {
  const double decl = solar_declination(day_of_year, solar_hours);
  const double h = solar_hour_angle(solar_hours);
  const double lat = latitude_deg * std::numbers::pi / 180;
  const double up = std::sin(lat) * std::sin(decl) + std::cos(lat) * std::cos(decl) * std::cos(h);
  const double east = -std::cos(decl) * std::sin(h);
  const double north = std::cos(lat) * std::sin(decl) - std::sin(lat) * std::cos(decl) * std::cos(h);
  return {east, up, -north};
}

}  // namespace volgraph::physics
