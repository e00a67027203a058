# All third-party libraries come from Debian packages (see scripts/setup); nothing is
# downloaded at build time.
find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(PkgConfig REQUIRED)
# PETSc's pkg-config file carries no MPI include path: link MPI::MPI_CXX alongside it.
pkg_check_modules(PETSC REQUIRED IMPORTED_TARGET PETSc)
pkg_check_modules(FFTW REQUIRED IMPORTED_TARGET fftw3)  # PkgConfig::FFTW: the fluid's pressure transforms

# python3-h5py pulls in the serial HDF5 runtime; PETSc loads the parallel one. Both must
# be the same library, so insist on the parallel build.
set(HDF5_PREFER_PARALLEL TRUE)
find_package(HDF5 REQUIRED COMPONENTS C)
if(NOT HDF5_IS_PARALLEL)
  message(FATAL_ERROR "cosim needs the parallel HDF5 (libhdf5-openmpi-dev); found a serial one")
endif()

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(yaml-cpp REQUIRED)
find_package(cppzmq REQUIRED)
find_package(CLI11 REQUIRED)
find_package(spdlog REQUIRED)
find_package(GTest REQUIRED)
find_package(benchmark REQUIRED)

# Rigid-body geometry and collision.
find_package(assimp REQUIRED)                             # assimp::assimp: STL and OBJ meshes
find_package(Qhull REQUIRED)                              # Qhull::qhullcpp, Qhull::qhull_r: convex hulls
pkg_check_modules(CCD REQUIRED IMPORTED_TARGET ccd)       # PkgConfig::CCD: GJK, EPA, MPR

# Tracker meshes. Debian's libgmsh-dev and voro++-dev ship no CMake or pkg-config files.
find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
add_library(Gmsh::gmsh UNKNOWN IMPORTED)
set_target_properties(Gmsh::gmsh PROPERTIES IMPORTED_LOCATION "${GMSH_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${GMSH_INCLUDE_DIR}")
find_path(VORO_INCLUDE_DIR voro++/voro++.hh REQUIRED)
find_library(VORO_LIBRARY voro++ REQUIRED)
add_library(Voro::voro UNKNOWN IMPORTED)
set_target_properties(Voro::voro PROPERTIES IMPORTED_LOCATION "${VORO_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${VORO_INCLUDE_DIR}")

# DSMC random numbers (tracker/dsmc): PCG, header-only; Debian's libpcg-cpp-dev ships no
# CMake or pkg-config files.
find_path(PCG_INCLUDE_DIR pcg_random.hpp REQUIRED)
add_library(Pcg::pcg INTERFACE IMPORTED)
set_target_properties(Pcg::pcg PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${PCG_INCLUDE_DIR}")

# The tracker's domain decomposition (tracker/parallel): METIS 5 graph partitioning;
# Debian's libmetis-dev ships no CMake or pkg-config files.
find_path(METIS_INCLUDE_DIR metis.h REQUIRED)
find_library(METIS_LIBRARY metis REQUIRED)
add_library(Metis::metis UNKNOWN IMPORTED)
set_target_properties(Metis::metis PROPERTIES IMPORTED_LOCATION "${METIS_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${METIS_INCLUDE_DIR}")
