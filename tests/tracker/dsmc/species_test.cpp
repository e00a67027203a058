// The species file: Bird's (1994) Appendix A values, their consistency with the viscosity,
// and errors that name the file, the key and the value.
#include "tracker/dsmc/species.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace cosim::tracker::dsmc {
namespace {

TEST(Species, DefaultFileHoldsBirdsValues) {
  const SpeciesTable table = read_species(default_species_file());
  const Species& ar = table.at("Ar");
  EXPECT_DOUBLE_EQ(ar.mass, 6.63e-26);
  EXPECT_DOUBLE_EQ(ar.diameter_vhs, 4.17e-10);
  EXPECT_DOUBLE_EQ(ar.diameter_vss, 4.11e-10);
  EXPECT_DOUBLE_EQ(ar.omega, 0.81);
  EXPECT_DOUBLE_EQ(ar.alpha, 1.40);
  EXPECT_DOUBLE_EQ(ar.T_ref, 273);
  EXPECT_EQ(ar.rotational_dof, 0);
  const Species& n2 = table.at("N2");
  EXPECT_DOUBLE_EQ(n2.mass, 4.65e-26);
  EXPECT_DOUBLE_EQ(n2.omega, 0.74);
  EXPECT_DOUBLE_EQ(n2.alpha, 1.36);
  EXPECT_EQ(n2.rotational_dof, 2);
  const Species& he = table.at("He");
  EXPECT_DOUBLE_EQ(he.mass, 6.65e-27);
  EXPECT_DOUBLE_EQ(he.diameter_vhs, 2.33e-10);
  EXPECT_DOUBLE_EQ(he.diameter_vss, 2.30e-10);
  EXPECT_DOUBLE_EQ(he.omega, 0.66);
  EXPECT_DOUBLE_EQ(he.alpha, 1.26);
}

// The VHS and VSS viscosities (Bird 1994, ch. 4) solved for the diameter at T_ref:
//   VHS: d^2 = 15 sqrt(m k T_ref / pi) / (2 (5 - 2 omega)(7 - 2 omega) mu_ref),
//   VSS: d^2 = 5 (alpha + 1)(alpha + 2) sqrt(m k T_ref / pi) / (4 alpha (5 - 2 omega)(7 - 2 omega) mu_ref).
// The tabulated values have three digits.
TEST(Species, DiametersReproduceTheViscosity) {
  const SpeciesTable table = read_species(default_species_file());
  for (const auto& [name, s] : table.all()) {
    const double root = std::sqrt(s.mass * boltzmann * s.T_ref / std::numbers::pi);
    const double w = (5 - 2 * s.omega) * (7 - 2 * s.omega);
    const double d_vhs = std::sqrt(15 * root / (2 * w * s.viscosity_ref));
    const double d_vss = std::sqrt(5 * (s.alpha + 1) * (s.alpha + 2) * root / (4 * s.alpha * w * s.viscosity_ref));
    EXPECT_NEAR(d_vhs / s.diameter_vhs, 1, 3e-3) << name;
    EXPECT_NEAR(d_vss / s.diameter_vss, 1, 3e-3) << name;
  }
}

class SpeciesErrors : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& text) {
    const auto path =
        std::filesystem::temp_directory_path() /
        ("dsmc_species_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".yaml");
    std::ofstream(path) << text;
    return path;
  }
  // The message of the error read_species throws for `text`.
  std::string error(const std::string& text) {
    const auto path = write(text);
    try {
      read_species(path);
    } catch (const SpeciesError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path.string()), std::string::npos) << what;
      return what;
    }
    ADD_FAILURE() << "no error for\n" << text;
    return {};
  }
  static std::string argon(const std::string& key, const std::string& value) {
    std::string text =
        "species:\n  Ar:\n    mass: 6.63e-26\n    diameter_vhs: 4.17e-10\n    diameter_vss: 4.11e-10\n"
        "    omega: 0.81\n    alpha: 1.40\n    T_ref: 273\n    viscosity_ref: 2.117e-5\n    rotational_dof: 0\n";
    const auto at = text.find("    " + key + ":");
    const auto end = text.find('\n', at);
    text.replace(at, end - at, "    " + key + ": " + value);
    return text;
  }
};

TEST_F(SpeciesErrors, ValuesOutOfRangeNameKeyAndValue) {
  std::string e = error(argon("mass", "-6.63e-26"));
  EXPECT_NE(e.find("species.Ar.mass"), std::string::npos) << e;
  EXPECT_NE(e.find("-6.63e-26"), std::string::npos) << e;
  EXPECT_NE(e.find(":3:"), std::string::npos) << e;  // the line
  e = error(argon("omega", "0.3"));
  EXPECT_NE(e.find("species.Ar.omega"), std::string::npos) << e;
  EXPECT_NE(e.find("'0.3'"), std::string::npos) << e;
  e = error(argon("alpha", "2.5"));
  EXPECT_NE(e.find("species.Ar.alpha"), std::string::npos) << e;
  EXPECT_NE(e.find("'2.5'"), std::string::npos) << e;
  e = error(argon("rotational_dof", "1"));
  EXPECT_NE(e.find("species.Ar.rotational_dof"), std::string::npos) << e;
  e = error(argon("T_ref", "0"));
  EXPECT_NE(e.find("species.Ar.T_ref"), std::string::npos) << e;
}

TEST_F(SpeciesErrors, NotANumber) {
  const std::string e = error(argon("diameter_vss", "4.11e-10m"));
  EXPECT_NE(e.find("species.Ar.diameter_vss"), std::string::npos) << e;
  EXPECT_NE(e.find("'4.11e-10m'"), std::string::npos) << e;
  EXPECT_NE(e.find("not a number"), std::string::npos) << e;
}

TEST_F(SpeciesErrors, UnknownAndMissingKeys) {
  std::string text = argon("omega", "0.81");
  text += "    omgea: 0.8\n";
  std::string e = error(text);
  EXPECT_NE(e.find("species.Ar.omgea"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key"), std::string::npos) << e;
  text = argon("alpha", "1.4");
  text.erase(text.find("    alpha"), std::string("    alpha: 1.4\n").size());
  e = error(text);
  EXPECT_NE(e.find("species.Ar.alpha"), std::string::npos) << e;
  EXPECT_NE(e.find("missing"), std::string::npos) << e;
  e = error("gases:\n  Ar: {}\n");
  EXPECT_NE(e.find("'gases'"), std::string::npos) << e;
  e = error("species: [\n");
  EXPECT_NE(e.find("invalid YAML"), std::string::npos) << e;
}

TEST(Species, UnknownSpeciesNamesTheFileAndTheKnownOnes) {
  const SpeciesTable table = read_species(default_species_file());
  try {
    table.at("Xe");
    FAIL();
  } catch (const SpeciesError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'Xe'"), std::string::npos) << what;
    EXPECT_NE(what.find("species.yaml"), std::string::npos) << what;
    EXPECT_NE(what.find("Ar, He, N2"), std::string::npos) << what;
  }
  EXPECT_THROW(read_species("/nonexistent/species.yaml"), SpeciesError);
}

}  // namespace
}  // namespace cosim::tracker::dsmc
