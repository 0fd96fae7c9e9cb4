// Inputs the fuzz harnesses (tests/fuzz/) found crashing or hitting undefined behaviour, kept in
// tests/data/fuzz/ as they were found; each must now be a clean InputError naming what is wrong.
#include <gtest/gtest.h>

#include <string>

#include "io/input_error.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"

namespace rayvec {
namespace {

const std::string kFuzz = std::string(RAYVEC_TEST_DATA) + "/fuzz/";

template <typename Load>
std::string input_error_of(Load load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(FuzzRegressions, SkinWeightJointIdBeyondIntIsRejected) {
  // `vw 0 2222222224`: tinyobjloader converted the joint id to int (UBSan: float-cast-overflow).
  const std::string path = kFuzz + "obj_vw_joint_overflow.obj";
  EXPECT_EQ(input_error_of([&] { load_obj(path); }),
            path + ":1: `vw` joint id '2222222224' is not a number below 2^31");
}

TEST(FuzzRegressions, JsonNumberOverflowIsAnInputError) {
  // nlohmann throws out_of_range (not parse_error) for 3.3e341: it escaped as an uncaught exception.
  const std::string path = kFuzz + "scene_number_overflow.json";
  EXPECT_EQ(input_error_of([&] { load_scene_json(path); }),
            path + ":1: invalid JSON: number overflow parsing '33333333.3331333e334'");
}

}  // namespace
}  // namespace rayvec
