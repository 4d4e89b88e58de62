// ordered_in_processes: items computed in forked workers, handed back in order; a worker's error,
// a worker that dies, and an interrupt of the consumer.
#include <catch2/catch.hpp>

#include <cerrno>
#include <set>
#include <stdexcept>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "kinergy/common/process.hpp"

namespace {

/// No child of this process is left unreaped.
bool no_children() {
  errno = 0;
  return waitpid(-1, nullptr, WNOHANG) == -1 && errno == ECHILD;
}

}  // namespace

TEST_CASE("ordered_in_processes: every item, in order, computed in the workers", "[process]") {
  const pid_t self = getpid();
  std::vector<std::size_t> order;
  std::set<std::string> pids;
  kinergy::ordered_in_processes(
      50, 3, [&](std::size_t i) { return std::to_string(i * i) + " " + std::to_string(getpid()); },
      [&](std::size_t i, const std::string& answer) {
        order.push_back(i);
        const auto space = answer.find(' ');
        CHECK(answer.substr(0, space) == std::to_string(i * i));
        pids.insert(answer.substr(space + 1));
      });
  REQUIRE(order.size() == 50);
  for (std::size_t i = 0; i < order.size(); ++i) CHECK(order[i] == i);
  CHECK(pids.size() == 3);
  CHECK(pids.count(std::to_string(self)) == 0);
  CHECK(no_children());
  // one job: here, in order
  std::string here;
  kinergy::ordered_in_processes(
      4, 1, [&](std::size_t i) { return std::to_string(i) + (getpid() == self ? "h" : "w"); },
      [&](std::size_t, const std::string& a) { here += a; });
  CHECK(here == "0h1h2h3h");
  // an empty answer and answers larger than a pipe's buffer come back whole
  std::size_t total = 0;
  kinergy::ordered_in_processes(
      6, 2, [](std::size_t i) { return std::string(i % 2 ? 300000 : 0, static_cast<char>('a' + i)); },
      [&](std::size_t i, const std::string& a) {
        CHECK(a.size() == (i % 2 ? 300000u : 0u));
        total += a.size();
      });
  CHECK(total == 900000);
}

TEST_CASE("ordered_in_processes: a worker's error after the answers before it, a dead worker, an interrupt", "[process][errors]") {
  std::vector<std::size_t> seen;
  auto consume = [&](std::size_t i, const std::string&) { seen.push_back(i); };
  // a worker throws at item 7: items 0 to 6 are consumed, then its message
  try {
    kinergy::ordered_in_processes(
        20, 2,
        [](std::size_t i) -> std::string {
          if (i == 7) throw std::invalid_argument("item seven is bad");
          return "ok";
        },
        consume);
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "item seven is bad");
  }
  CHECK(seen == std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6});
  CHECK(no_children());
  // a worker that ends without answering (as if killed)
  seen.clear();
  try {
    kinergy::ordered_in_processes(
        10, 2,
        [](std::size_t i) -> std::string {
          if (i == 4) _exit(3);
          return "ok";
        },
        consume);
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("a worker process ended without answering item 4") == 0);
  }
  CHECK(seen == std::vector<std::size_t>{0, 1, 2, 3});
  CHECK(no_children());
  // the consumer stops (an interrupt): every worker is killed and reaped
  struct Stop {};
  CHECK_THROWS_AS(kinergy::ordered_in_processes(
                      1000, 2,
                      [](std::size_t) {
                        usleep(1000);
                        return std::string("slow");
                      },
                      [](std::size_t i, const std::string&) {
                        if (i == 2) throw Stop{};
                      }),
                  Stop);
  CHECK(no_children());
  CHECK(kinergy::available_cores() >= 1);
}
