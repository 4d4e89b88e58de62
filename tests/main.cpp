#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "kinergy/common/error.hpp"

int main(int argc, char** argv) {
  kinergy::reproducible_process(argc, argv);  // the same term order as the CLI
  return Catch::Session().run(argc, argv);
}
