#include "bench/fluid_throughput/openfoam_case.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cosim::bench {
namespace {

namespace fs = std::filesystem;

// Where the OpenFOAM environment script may be: an already sourced installation first, then
// Debian's package, then the openfoam.com packages.
fs::path openfoam_bashrc() {
  std::vector<fs::path> candidates;
  if (const char* dir = std::getenv("WM_PROJECT_DIR")) candidates.emplace_back(fs::path(dir) / "etc/bashrc");
  for (const char* p : {"/usr/share/openfoam/etc/bashrc", "/usr/lib/openfoam/openfoam1912/etc/bashrc",
                        "/usr/lib/openfoam/openfoam/etc/bashrc"})
    candidates.emplace_back(p);
  for (const fs::path& p : candidates)
    if (fs::exists(p)) return p;
  throw std::runtime_error(
      "--openfoam: no OpenFOAM found (looked for etc/bashrc under $WM_PROJECT_DIR, /usr/share/openfoam, "
      "/usr/lib/openfoam/openfoam1912); on Debian: apt-get install openfoam");
}

// Runs `command` in `dir` with the OpenFOAM environment and otherwise a clean one: under
// mpirun this process's environment carries its own launcher's variables, which would
// make a nested mpirun join the wrong job. Only the Open MPI settings a user chooses
// (running as root, shared-memory transport, oversubscription) are passed on. True when
// the command succeeded.
bool run_in_case(const fs::path& bashrc, const fs::path& dir, const std::string& command, const std::string& log) {
  std::string env = "env -i PATH=/usr/local/bin:/usr/bin:/bin";
  for (const char* name : {"HOME", "OMPI_ALLOW_RUN_AS_ROOT", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "OMPI_MCA_btl",
                           "OMPI_MCA_rmaps_base_oversubscribe"})
    if (const char* value = std::getenv(name)) env += std::string(" ") + name + "='" + value + "'";
  // The Debian bashrc complains about helper scripts it does not ship; its variables are set.
  const std::string script = "source '" + bashrc.string() + "' >/dev/null 2>&1; cd '" + dir.string() + "' && { " +
                             command + "; } > " + log + " 2>&1";
  const std::string shell = env + " bash -c \"" + script + "\"";
  return std::system(shell.c_str()) == 0;
}

void run_step(const fs::path& bashrc, const fs::path& dir, const std::string& command, const std::string& log) {
  if (!run_in_case(bashrc, dir, command, log))
    throw std::runtime_error("OpenFOAM: '" + command + "' failed, see " + (dir / log).string());
}

void write(const fs::path& file, const std::string& object, const std::string& cls, const std::string& body) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file);
  out << "FoamFile { version 2.0; format ascii; class " << cls << "; object " << object << "; }\n" << body;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

// The tutorial cavity's numerics (Euler in time, central convection, PISO with two
// corrections, GAMG for p), on our cube with the lid at z = 1.
void write_case(const fs::path& dir, const Cavity& c, int ranks) {
  std::ostringstream mesh, control, transport, decompose;
  mesh << "convertToMeters 1;\n"
          "vertices ((0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1));\n"
       << "blocks (hex (0 1 2 3 4 5 6 7) (" << c.n << ' ' << c.n << ' ' << c.n << ") simpleGrading (1 1 1));\n"
       << "boundary (\n  lid { type wall; faces ((4 5 6 7)); }\n"
          "  walls { type wall; faces ((0 3 2 1) (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }\n);\n";
  write(dir / "system/blockMeshDict", "blockMeshDict", "dictionary", mesh.str());
  control.precision(17);
  control << "application icoFoam; startFrom startTime; startTime 0; stopAt endTime;\n"
          << "endTime " << c.end_time() << "; deltaT " << c.dt() << ";\n"
          << "writeControl timeStep; writeInterval " << c.steps
          << "; purgeWrite 0;\n"
             "writeFormat ascii; writePrecision 12; writeCompression off;\n"
             "timeFormat general; timePrecision 12; runTimeModifiable false;\n";
  write(dir / "system/controlDict", "controlDict", "dictionary", control.str());
  write(dir / "system/fvSchemes", "fvSchemes", "dictionary",
        "ddtSchemes { default Euler; }\ngradSchemes { default Gauss linear; }\n"
        "divSchemes { default none; div(phi,U) Gauss linear; }\n"
        "laplacianSchemes { default Gauss linear orthogonal; }\n"
        "interpolationSchemes { default linear; }\nsnGradSchemes { default orthogonal; }\n");
  write(dir / "system/fvSolution", "fvSolution", "dictionary",
        "solvers {\n  p { solver GAMG; smoother GaussSeidel; tolerance 1e-06; relTol 0.05; }\n"
        "  pFinal { $p; relTol 0; }\n"
        "  U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-05; relTol 0; }\n}\n"
        "PISO { nCorrectors 2; nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }\n");
  decompose << "numberOfSubdomains " << ranks << "; method simple; coeffs { n (1 1 " << ranks << "); }\n";
  write(dir / "system/decomposeParDict", "decomposeParDict", "dictionary", decompose.str());
  transport.precision(17);
  transport << "nu " << c.viscosity() << ";\n";
  write(dir / "constant/transportProperties", "transportProperties", "dictionary", transport.str());
  std::ostringstream u;
  u << "dimensions [0 1 -1 0 0 0 0]; internalField uniform (0 0 0);\nboundaryField {\n  lid { type fixedValue; value "
       "uniform ("
    << Cavity::kLidVelocity << " 0 0); }\n  walls { type noSlip; }\n}\n";
  write(dir / "0/U", "U", "volVectorField", u.str());
  write(dir / "0/p", "p", "volScalarField",
        "dimensions [0 2 -2 0 0 0 0]; internalField uniform 0;\n"
        "boundaryField { lid { type zeroGradient; } walls { type zeroGradient; } }\n");
}

// The cumulative "ExecutionTime = t s" after each step.
std::vector<double> execution_times(const fs::path& log) {
  std::ifstream in(log);
  std::vector<double> times;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("ExecutionTime = ", 0) == 0) times.push_back(std::stod(line.substr(16)));
  return times;
}

// The latest time directory: the one the run wrote at its end.
fs::path latest_time(const fs::path& dir) {
  fs::path latest;
  double newest = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    char* end = nullptr;
    const std::string name = e.path().filename().string();
    const double t = std::strtod(name.c_str(), &end);
    if (e.is_directory() && *end == '\0' && t > newest) latest = e.path(), newest = t;
  }
  if (latest.empty()) throw std::runtime_error("OpenFOAM: no time directory written in " + dir.string());
  return latest;
}

// u(0.5, 0.5, z) from the cell-centred U: the mean of the four cells around the centre
// line (blockMesh numbers the cells x fastest, then y, then z).
std::vector<double> centre_line(const fs::path& u_file, int n) {
  std::ifstream in(u_file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::size_t list = s.find("List<vector>", s.find("internalField"));
  if (list == std::string::npos)
    throw std::runtime_error("OpenFOAM: no nonuniform internalField in " + u_file.string());
  const char* p = s.c_str() + list + 12;
  char* end = nullptr;
  const long count = std::strtol(p, &end, 10);
  if (count != static_cast<long>(n) * n * n)
    throw std::runtime_error("OpenFOAM: unexpected cell count in " + u_file.string());
  std::vector<double> line(static_cast<std::size_t>(n), 0.0);
  p = std::strchr(end, '(') + 1;  // the list
  for (long cell = 0; cell < count; ++cell) {
    p = std::strchr(p, '(') + 1;  // this cell's vector
    const double u = std::strtod(p, &end);
    p = end;
    const long i = cell % n, j = cell / n % n, k = cell / (static_cast<long>(n) * n);
    if ((i == n / 2 - 1 || i == n / 2) && (j == n / 2 - 1 || j == n / 2)) line[static_cast<std::size_t>(k)] += 0.25 * u;
  }
  return line;
}

}  // namespace

void require_openfoam(int ranks) {
  std::string tools = "blockMesh icoFoam";
  if (ranks > 1) tools += " decomposePar reconstructPar mpirun";
  std::string all_found = "true";
  std::istringstream names(tools);
  for (std::string name; names >> name;) all_found += " && command -v " + name;
  const fs::path bashrc = openfoam_bashrc();
  if (!run_in_case(bashrc, fs::temp_directory_path(), all_found, "/dev/null"))
    throw std::runtime_error("--openfoam: " + tools + " not all found after sourcing " + bashrc.string());
}

ThroughputRun run_openfoam(const Cavity& cavity, int ranks) {
  if (cavity.steps < 3) throw std::invalid_argument("--openfoam needs --steps >= 3");
  const fs::path bashrc = openfoam_bashrc();
  const bool parallel = ranks > 1;
  std::string pattern = (fs::temp_directory_path() / "fluid_throughput_openfoam_XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary directory");
  const fs::path dir = pattern;
  write_case(dir, cavity, ranks);
  run_step(bashrc, dir, "blockMesh", "log.blockMesh");
  if (parallel) run_step(bashrc, dir, "decomposePar -force", "log.decomposePar");
  const auto start = std::chrono::steady_clock::now();
  run_step(bashrc, dir, parallel ? "mpirun -n " + std::to_string(ranks) + " icoFoam -parallel" : "icoFoam",
           "log.icoFoam");
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  if (parallel) run_step(bashrc, dir, "reconstructPar -latestTime", "log.reconstructPar");

  const std::vector<double> times = execution_times(dir / "log.icoFoam");
  if (static_cast<int>(times.size()) != cavity.steps)
    throw std::runtime_error("OpenFOAM: expected " + std::to_string(cavity.steps) + " steps in " +
                             (dir / "log.icoFoam").string());
  ThroughputRun run;
  run.timed_steps = cavity.steps - 2;
  run.first_step_seconds = times.front();
  run.cpu_seconds_per_step = (times[times.size() - 2] - times.front()) / run.timed_steps;
  run.centre_line = centre_line(latest_time(dir) / "U", cavity.n);
  std::printf("OpenFOAM %d^3 on %d rank(s): icoFoam took %.1f s wall in all\n", cavity.n, ranks, wall.count());
  fs::remove_all(dir);
  return run;
}

}  // namespace cosim::bench
