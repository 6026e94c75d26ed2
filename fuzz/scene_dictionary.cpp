// Prints every key of the scene schema, and the names of its enumerations, as a libFuzzer
// dictionary: the fuzzer then writes keys a scene can hold instead of guessing them.
#include <cstdio>
#include <set>
#include <string>

#include "scene/scene_schema.hpp"

namespace {

// A dictionary entry for a JSON string: "\"name\"", quotes included, as a scene writes it.
std::string quoted(const std::string& word) {
  return "\"\\\"" + word + "\\\"\"";
}

void collect(const sph::scene::KeySchema& level, std::set<std::string>& words) {
  if (!level.name.empty() && level.name != "[]") words.insert(quoted(level.name));
  for (const sph::scene::KeySchema& child : level.children) collect(child, words);
}

template <class Names>
void names(const Names& list, std::set<std::string>& words) {
  for (const auto& named : list) words.insert(quoted(named.name));
}

}  // namespace

int main() {
  using namespace sph::scene;
  std::set<std::string> words;
  collect(sceneSchema(), words);
  names(kOutsideNames, words);
  names(kKernelNames, words);
  names(kEosNames, words);
  names(kPressureFormNames, words);
  names(kSolverNames, words);
  names(kCouplingNames, words);
  names(kViscosityNames, words);
  names(kFormatNames, words);
  names(kWallKindNames, words);
  names(kFluidSideNames, words);
  names(kProbeKindNames, words);
  names(kMotionNames, words);
  names(kDeformableModelNames, words);
  names(kShapeNames, words);
  for (const std::string& word : words) std::printf("%s\n", word.c_str());
  return 0;
}
