// wire_seeds <dir>: writes the seed corpus of fuzz_wire, one file per kind of message the
// coupler and its participants exchange, framed as frames.hpp reads them.
#include <fstream>
#include <iostream>
#include <string>

#include "coupler/protocol/message.hpp"
#include "tests/fuzz/frames.hpp"

namespace {

using namespace cosim::protocol;

Message message(Type type, std::vector<Array> arrays) {
  Message m;
  m.header.type = type;
  m.header.participant = "fluid";
  m.header.window = 3;
  m.header.iteration = 1;
  m.header.t0 = 0.3;
  m.header.t1 = 0.4;
  m.arrays = std::move(arrays);
  return m;
}

void write(const std::string& dir, const std::string& name, const Message& m) {
  std::string out;
  for (const auto& frame : encode(m))
    cosim::fuzz::append_frame(out, {static_cast<const std::byte*>(frame.data()), frame.size()});
  std::ofstream(dir + "/" + name, std::ios::binary) << out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: wire_seeds <dir>\n";
    return 2;
  }
  const std::string dir = argv[1];
  Message hello = message(Type::Hello, {});
  hello.header.provides = 2;
  hello.header.needs = 1;
  hello.header.ranks = 2;
  write(dir, "hello", hello);
  write(dir, "init",
        message(Type::Init, {Array::text("scene.yaml"), Array::text("time: {end: 1}\n"),
                             Array::of(Tag::Poses, 1, kPoseWidth, std::vector<double>(kPoseWidth, 0.5))}));
  write(dir, "advance",
        message(Type::Advance, {Array::of(Tag::Poses, 2, kPoseWidth, std::vector<double>(2 * kPoseWidth, 1.0)),
                                Array::of(Tag::Forces, 2, kForceWidth, std::vector<double>(2 * kForceWidth, -2.0))}));
  write(
      dir, "result",
      message(Type::Result, {Array::of(Tag::Forces, 1, kForceWidth, std::vector<double>(kForceWidth, 3.0)),
                             Array::of(Tag::Stats, 1, kStatsWidth, {4, 0.25}),
                             Array::of(Tag::Responses, 1, kResponseWidth, std::vector<double>(kResponseWidth, 0.0))}));
  write(dir, "state", message(Type::State, {Array::of(Tag::State, 1, 4, {1, 2, 3, 4})}));
  write(dir, "field",
        message(Type::Field, {Array::text("x"), Array::of(Tag::Field, 1, 3, {0, 0.5, 1}), Array::text("p"),
                              Array::of(Tag::Field, 2, 1, {7, 8}), Array::of(Tag::Points, 2, 3, {0, 0, 0, 1, 1, 1}),
                              Array::of(Tag::PointAttributes, 1, 2, {5, 6})}));
  write(dir, "error", message(Type::Error, {Array::text("the solver diverged")}));
  write(dir, "stop", message(Type::Stop, {}));
}
