// libFuzzer target: any bytes as a scene, loaded, built into a model and solved. A bad scene must
// end in a SceneError (one line naming its place); anything else — another exception, a crash, a
// sanitizer report, a hang, memory without bound — is a finding. Run by tests/fuzz/run.sh.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    kinergy::Solution s = kinergy::solve_scene(kinergy::scene::load_string(text, "fuzz.yaml"));
    (void)s;
  } catch (const kinergy::SceneError&) {
    // the expected end of a bad scene
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kinergy_fuzz: an internal error escaped: %s\n", e.what());
    std::abort();
  }
  return 0;
}
