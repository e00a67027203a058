// Signed-distance queries per second (items_per_second), world frame through a pose, in
// batches as the fluid's FBM indicator issues them. Not a test: run bench_geometry.
#include <benchmark/benchmark.h>

#include "tests/geometry/fixtures.hpp"
#include "geometry/distance_map.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

constexpr int batch = 100000;

const Pose& pose() {
  static const Pose p({0.3, -0.2, 0.1},
                      Eigen::Quaterniond(Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 1, 0).normalized())));
  return p;
}

const TriangleMesh& torus() {  // 80 x 32 x 2 = 5120 triangles, non-convex
  static const TriangleMesh mesh = testing::make_mesh(testing::torus_mesh(1.0, 0.3, 80, 32));
  return mesh;
}

// Random points in the shape's world box grown by 20%.
std::vector<Eigen::Vector3d> random_points(const Shape& shape) {
  const Aabb box = world_aabb(shape, pose());
  const Eigen::Vector3d c = 0.5 * (box.min + box.max), h = 0.6 * (box.max - box.min);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points(batch);
  for (auto& p : points) p = c + h.cwiseProduct(Eigen::Vector3d(u(rng), u(rng), u(rng)));
  return points;
}

// The same box sampled as a fluid grid is (x fastest), about `batch` nodes.
GridSpec grid_over(const Shape& shape) {
  const Aabb box = world_aabb(shape, pose());
  const Eigen::Vector3d extent = 1.2 * (box.max - box.min);
  const double h = std::cbrt(extent.prod() / batch);
  GridSpec g{0.5 * (box.min + box.max) - 0.5 * extent, h, {}};
  for (int a = 0; a < 3; ++a) g.count[a] = static_cast<int>(extent[a] / h) + 1;
  return g;
}

void run_points(benchmark::State& state, const Shape& shape) {
  const auto points = random_points(shape);
  std::vector<double> out(points.size());
  for (auto _ : state) {
    signed_distances(shape, pose(), points, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}

void run_grid(benchmark::State& state, const Shape& shape) {
  const GridSpec grid = grid_over(shape);
  std::vector<double> out(grid.size());
  for (auto _ : state) {
    signed_distances(shape, pose(), grid, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(grid.size()));
}

void BM_Sphere(benchmark::State& s) { run_points(s, Sphere(0.7)); }
void BM_Box(benchmark::State& s) { run_points(s, Box({0.9, 0.4, 0.6})); }
void BM_Ellipsoid(benchmark::State& s) { run_points(s, Ellipsoid({1.2, 0.5, 0.8})); }
void BM_Cylinder(benchmark::State& s) { run_points(s, Cylinder(0.5, 1.6)); }
void BM_Mesh5k_RandomPoints(benchmark::State& s) { run_points(s, torus()); }
void BM_Mesh5k_GridOrder(benchmark::State& s) { run_grid(s, torus()); }

void BM_Mesh5k_DistanceMap(benchmark::State& state) {
  const DistanceMap map(torus(), static_cast<double>(state.range(0)) / 1000.0, 0.1);
  const auto points = random_points(torus());
  for (auto _ : state) {
    double sum = 0.0;
    for (const auto& p : points) sum += map.signed_distance(pose().to_body(p));
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
  state.counters["nodes"] = static_cast<double>(map.grid().size());
}

void BM_Mesh5k_DistanceMapBuild(benchmark::State& state) {
  for (auto _ : state) {
    const DistanceMap map(torus(), 0.04, 0.1);
    benchmark::DoNotOptimize(map.values().data());
    state.SetItemsProcessed(static_cast<std::int64_t>(map.grid().size()));
  }
}

BENCHMARK(BM_Sphere)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Box)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ellipsoid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Cylinder)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mesh5k_RandomPoints)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mesh5k_GridOrder)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mesh5k_DistanceMap)->Arg(40)->Arg(20)->Unit(benchmark::kMillisecond);  // spacing in 1e-3
BENCHMARK(BM_Mesh5k_DistanceMapBuild)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace cosim::geometry

BENCHMARK_MAIN();
