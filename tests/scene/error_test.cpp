#include "coupler/scene/error.hpp"

#include <gtest/gtest.h>

using cosim::scene::SceneError;

TEST(SceneError, NamesFileLineKeyAndValue) {
  const SceneError e("scene.yaml", 7, "bodies[0].shape.radius", "-0.01", "must be > 0");
  EXPECT_STREQ(e.what(), "scene.yaml:7: bodies[0].shape.radius = -0.01: must be > 0");
  EXPECT_EQ(e.file, "scene.yaml");
  EXPECT_EQ(e.line, 7);
  EXPECT_EQ(e.key, "bodies[0].shape.radius");
  EXPECT_EQ(e.value, "-0.01");
}

TEST(SceneError, LeavesOutWhatItDoesNotHave) {
  EXPECT_STREQ(SceneError("s.yaml", 3, "domain", "", "missing required key").what(),
               "s.yaml:3: domain: missing required key");
  EXPECT_STREQ(SceneError("s.yaml", 3, "", "", "invalid YAML").what(), "s.yaml:3: invalid YAML");
  EXPECT_STREQ(SceneError("s.yaml", 0, "", "", "no such scene file").what(), "s.yaml: no such scene file");
}
