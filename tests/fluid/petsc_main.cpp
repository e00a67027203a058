// GoogleTest main for the fluid tests: PETSc (and MPI) initialised once per process, and
// only rank 0 reports, so an mpirun of several ranks reads like a serial run.
#include <gtest/gtest.h>
#include <petscsys.h>

#include <cstdlib>

#ifdef __SANITIZE_ADDRESS__
// Open MPI's allocations live until the process exits. Suppress them, with full stacks so
// that every one passes through an Open MPI frame, and keep leak checking for the rest.
// PETSc 3.18 also drops the names PetscOptionsBegin copied when an option is refused.
extern "C" const char* __lsan_default_options() { return "fast_unwind_on_malloc=0"; }
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libmpi.so\nleak:libopen-pal.so\nleak:libopen-rte.so\nleak:libhwloc.so\nleak:libpmix.so\n"
         "leak:libevent\nleak:mca_\nleak:PetscOptionsBegin_Private\n";
}
#endif

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  // Listing the tests (gtest_discover_tests, at build time) needs no MPI.
  if (GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();
#ifdef __SANITIZE_ADDRESS__
  // Keep Open MPI's plug-ins loaded at exit so the leak report can name their frames.
  setenv("OMPI_MCA_mca_base_component_disable_dlclose", "1", 0);
#endif
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscMPIInt rank = 0;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (rank != 0)
    delete ::testing::UnitTest::GetInstance()->listeners().Release(
        ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  const int result = RUN_ALL_TESTS();
  PetscCall(PetscFinalize());
  return result;
}
