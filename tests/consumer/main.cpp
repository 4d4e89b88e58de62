// Solve a scene with the installed library and print each result's name, closed form and value.
//   consumer SCENE
#include <iostream>

#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: consumer SCENE\n";
    return 2;
  }
  try {
    const kinergy::Solution s = kinergy::solve_file(argv[1]);
    for (const auto& r : s.results)
      std::cout << r.name << " = " << r.closed << " = " << (r.si ? r.si->to_double() : 0.0) << "\n";
  } catch (const kinergy::SceneError& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
