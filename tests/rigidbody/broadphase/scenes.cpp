#include "tests/rigidbody/broadphase/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

namespace cosim::rigidbody::broadphase::scenes {

namespace {

using Rng = std::mt19937_64;

double log_uniform(Rng& rng, double lo, double hi) {
  return lo * std::pow(hi / lo, std::uniform_real_distribution<double>(0.0, 1.0)(rng));
}

Eigen::Vector3d point_in(Rng& rng, Box box) {
  std::uniform_real_distribution<double> u(box.lo, box.hi);
  const double x = u(rng);
  const double y = u(rng);
  return {x, y, u(rng)};
}

std::vector<Object> with_shuffled_ids(std::vector<Object> objects, Rng& rng) {
  std::vector<Id> ids(objects.size());
  std::iota(ids.begin(), ids.end(), Id{0});
  std::shuffle(ids.begin(), ids.end(), rng);
  for (std::size_t i = 0; i < objects.size(); ++i) objects[i].id = ids[i];
  return objects;
}

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

}  // namespace

std::vector<Object> uniform(std::size_t n, Box box, double r_min, double r_max, std::uint32_t seed) {
  Rng rng(seed);
  std::vector<Object> objects(n);
  for (Object& o : objects) {
    o.centre = point_in(rng, box);
    o.radius = log_uniform(rng, r_min, r_max);
  }
  return with_shuffled_ids(std::move(objects), rng);
}

std::vector<Object> clustered(std::size_t n, std::size_t clusters, double sigma, Box box, double r_min, double r_max,
                              std::uint32_t seed) {
  Rng rng(seed);
  std::vector<Eigen::Vector3d> centres(clusters);
  for (Eigen::Vector3d& c : centres) c = point_in(rng, box);
  std::normal_distribution<double> spread(0.0, sigma);
  std::uniform_int_distribution<std::size_t> pick(0, clusters - 1);
  std::vector<Object> objects(n);
  for (Object& o : objects) {
    const Eigen::Vector3d& c = centres[pick(rng)];
    const double x = spread(rng);
    const double y = spread(rng);
    o.centre = c + Eigen::Vector3d(x, y, spread(rng));
    o.radius = log_uniform(rng, r_min, r_max);
  }
  return with_shuffled_ids(std::move(objects), rng);
}

std::vector<Object> packed(std::size_t n, double phi, std::uint32_t seed) {
  Rng rng(seed);
  const double spacing = std::cbrt(sphere_volume(1.0) / phi);
  const auto side = static_cast<std::size_t>(std::ceil(std::cbrt(static_cast<double>(n))));
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<Object> objects(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d site(static_cast<double>(i % side), static_cast<double>(i / side % side),
                               static_cast<double>(i / side / side));
    const double x = jitter(rng);
    const double y = jitter(rng);
    objects[i].centre = spacing * site + Eigen::Vector3d(x, y, jitter(rng));
    objects[i].radius = 1.0;
  }
  return with_shuffled_ids(std::move(objects), rng);
}

std::vector<Object> polydisperse(std::size_t n, double phi, double ratio, std::uint32_t seed) {
  Rng rng(seed);
  std::vector<Object> objects(n);
  double volume = 0.0;
  for (Object& o : objects) {
    o.radius = log_uniform(rng, 1.0, ratio);
    volume += sphere_volume(o.radius);
  }
  const Box box{0.0, std::cbrt(volume / phi)};
  for (Object& o : objects) o.centre = point_in(rng, box);
  return with_shuffled_ids(std::move(objects), rng);
}

}  // namespace cosim::rigidbody::broadphase::scenes
