#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "bench/rigidbody_granular/liggghts.hpp"

namespace cosim::bench {

namespace {

// Round trip exact, so LIGGGHTS starts from the other engines' doubles.
std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

}  // namespace

void write_liggghts_data(const PourScene& scene, const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  double top = 0;
  for (const Eigen::Vector3d& p : scene.positions) top = std::max(top, p.z() + 2 * scene.radius);
  const std::string w = number(scene.half_width);
  out << "poured spheres, bench/rigidbody_granular\n\n"
      << scene.positions.size() << " atoms\n1 atom types\n\n"
      << "-" << w << " " << w << " xlo xhi\n-" << w << " " << w << " ylo yhi\n0 " << number(top) << " zlo zhi\n\n"
      << "Atoms\n\n";
  // atom_style granular: id type diameter density x y z
  for (std::size_t i = 0; i < scene.positions.size(); ++i) {
    const Eigen::Vector3d& p = scene.positions[i];
    out << i + 1 << " 1 " << number(2 * scene.radius) << " " << number(scene.density) << " " << number(p.x()) << " "
        << number(p.y()) << " " << number(p.z()) << "\n";
  }
  // id vx vy vz omegax omegay omegaz
  out << "\nVelocities\n\n";
  for (std::size_t i = 0; i < scene.velocities.size(); ++i) {
    const Eigen::Vector3d& v = scene.velocities[i];
    out << i + 1 << " " << number(v.x()) << " " << number(v.y()) << " " << number(v.z()) << " 0 0 0\n";
  }
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

std::string liggghts_deck(const PourScene& scene, int steps, int thermo_every, const std::string& data_file,
                          const std::string& dump_file) {
  const std::string w = number(scene.half_width);
  const std::string wall = "all wall/gran model hertz tangential history primitive type 1 ";
  std::string deck;
  const auto line = [&deck](const std::string& text) { deck += text + "\n"; };
  line("# The poured spheres of bench/rigidbody_granular: Hertz-Mindlin on one core.");
  line("atom_style granular");
  line("atom_modify map array");
  // Fixed sides (the walls are fixes at the box's faces); the top grows with the spheres.
  line("boundary f f m");
  line("newton off");
  line("communicate single vel yes");
  line("units si");
  line("read_data " + data_file);
  // The skin is the other engines' contact margin.
  line("neighbor " + number(scene.margin) + " bin");
  line("neigh_modify delay 0");
  line("fix m1 all property/global youngsModulus peratomtype " + number(scene.hertz.young));
  line("fix m2 all property/global poissonsRatio peratomtype " + number(scene.hertz.poisson));
  line("fix m3 all property/global coefficientRestitution peratomtypepair 1 " + number(scene.hertz.restitution));
  line("fix m4 all property/global coefficientFriction peratomtypepair 1 " + number(scene.friction));
  line("pair_style gran model hertz tangential history");
  line("pair_coeff * *");
  line("timestep " + number(scene.dem_dt));
  line("fix gravity all gravity 9.81 vector 0.0 0.0 -1.0");
  line("fix floor " + wall + "zplane 0.0");
  line("fix x_low " + wall + "xplane -" + w);
  line("fix x_high " + wall + "xplane " + w);
  line("fix y_low " + wall + "yplane -" + w);
  line("fix y_high " + wall + "yplane " + w);
  line("fix integrate all nve/sphere");
  line("compute translational all ke");
  line("compute rotational all erotate/sphere");
  line("thermo_style custom step atoms c_translational c_rotational");
  line("thermo " + std::to_string(thermo_every));
  line("thermo_modify norm no");
  line("run " + std::to_string(steps));
  line("write_dump all custom " + dump_file + " id x y z radius");
  return deck;
}

}  // namespace cosim::bench
