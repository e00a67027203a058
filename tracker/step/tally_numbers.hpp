// A tally's numbers in one fixed order, for the state arrays (simulation_state.cpp) and the
// sums over the ranks (simulation.cpp): each_count(t, f) calls f on every counter, then
// each_value(t, f) on every real number; `Tally` may be const.
#pragma once

#include <type_traits>

#include "tracker/tracking/obstacles.hpp"

namespace cosim::tracker::step::detail {

template <typename Tally>
constexpr bool kIsObstacleTally = std::is_same_v<std::remove_const_t<Tally>, tracking::ObstacleTally>;

template <typename Tally, typename F>
void each_count(Tally& t, F&& f) {
  f(t.hits);
  f(t.absorbed);
  if constexpr (kIsObstacleTally<Tally>) {
    f(t.entered);
    f(t.left);
    f(t.released);
    f(t.overrun);
  }
}

template <typename Tally, typename F>
void each_value(Tally& t, F&& f) {
  for (int i = 0; i < 3; ++i) f(t.impulse[i]);
  f(t.energy);
  if constexpr (kIsObstacleTally<Tally>)
    for (int i = 0; i < 3; ++i) f(t.angular_impulse[i]);
}

}  // namespace cosim::tracker::step::detail
