// newton::solve_bracketed_secant (Illinois regula falsi) against closed-form roots, and against
// bisection's evaluation count on functions where plain regula falsi stalls; parallel_for runs every
// item once and reports the error of the lowest failing item whatever the scheduling; start_in_background
// returns the work's value or exception and runs it at the lowest priority, the caller's unchanged;
// parallel_workers follows the affinity mask and the thread budget (COOLINGGEN_THREADS), and on one
// worker background work runs in the caller.
#define BOOST_TEST_MODULE secant_and_parallel
#include <boost/test/unit_test.hpp>

#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "src/core/background.hpp"
#include "src/core/newton.hpp"
#include "src/core/parallel.hpp"

using namespace cg;

BOOST_AUTO_TEST_CASE(illinois_finds_closed_form_roots_in_few_evaluations) {
  struct Case {
    double (*f)(double);
    double lo, hi, root;
  };
  const Case cases[] = {
      {[](double x) { return x * x * x - 2; }, 0.0, 2.0, std::cbrt(2.0)},
      // Convex and flat on one side: plain regula falsi keeps one end for ever (hundreds of steps).
      {[](double x) { return std::pow(x, 10) - 0.5; }, 0.0, 1.0, std::pow(0.5, 0.1)},
      {[](double x) { return std::exp(x) - 1e4; }, 0.0, 20.0, std::log(1e4)},
      // Decreasing: f(lo) > 0 > f(hi).
      {[](double x) { return std::cos(x) - x; }, 0.0, 1.0, 0.7390851332151607},
  };
  for (const Case& c : cases) {
    int evaluations = 0;
    auto f = [&](double x) {
      ++evaluations;
      return c.f(x);
    };
    const double x = newton::solve_bracketed_secant(f, c.lo, c.hi, c.f(c.lo), c.f(c.hi), 1e-14);
    BOOST_TEST(std::abs(x - c.root) <= 2e-14 * (1 + std::abs(c.root)));
    // Bisection needs log2(width / 1e-14) ~ 47 .. 51 evaluations for the same bracket.
    BOOST_TEST(evaluations <= 30, "evaluations " << evaluations);
  }
  // A root at a bracket end, and |f| <= ftol ending early at that point.
  auto line = [](double x) { return x - 0.25; };
  BOOST_TEST(newton::solve_bracketed_secant(line, 0.25, 1.0, 0.0, 0.75, 1e-14) == 0.25);
  const double early = newton::solve_bracketed_secant(line, 0.0, 1.0, -0.25, 0.75, 1e-14, 1e-3);
  BOOST_TEST(std::abs(early - 0.25) <= 1e-3);
}

BOOST_AUTO_TEST_CASE(parallel_for_runs_every_item_once_and_rethrows_the_lowest_error) {
  for (int workers : {1, 2, 4}) {
    std::vector<std::atomic<int>> hits(1000);
    std::atomic<int> bad_worker{0};  // (Boost.Test's macros are not for worker threads)
    parallel_for(1000, workers, [&](int i, int w) {
      if (w < 0 || w >= workers) ++bad_worker;
      ++hits[static_cast<std::size_t>(i)];
    });
    int wrong = 0;
    for (auto& h : hits) wrong += h != 1;
    BOOST_TEST(wrong == 0);
    BOOST_TEST(bad_worker == 0);
    // Items 300 and 700 throw: the error of 300 is reported, however the items were scheduled.
    for (int repeat = 0; repeat < 20; ++repeat) {
      std::string what;
      try {
        parallel_for(1000, workers, [&](int i, int) {
          if (i == 300 || i == 700) throw std::runtime_error("item " + std::to_string(i));
        });
      } catch (const std::runtime_error& e) {
        what = e.what();
      }
      BOOST_TEST(what == "item 300");
    }
  }
  parallel_for(0, 2, [](int, int) { throw std::runtime_error("no items: never called"); });
}

// The CPUs are those the affinity mask allows (a mask of one CPU set on this thread: 1), the budget caps
// them, a budget above them does not add threads, and a budget that is not a whole number in [1, 1024]
// reads as -1 and is ignored.
BOOST_AUTO_TEST_CASE(parallel_workers_follow_the_affinity_and_the_budget) {
  unsetenv("COOLINGGEN_THREADS");
  cpu_set_t mask;
  BOOST_TEST_REQUIRE(sched_getaffinity(0, sizeof mask, &mask) == 0);
  const int cpus = CPU_COUNT(&mask);
  BOOST_TEST(available_cpus() == cpus);
  BOOST_TEST(thread_budget() == 0);
  BOOST_TEST(parallel_workers() == cpus);
  cpu_set_t one;
  CPU_ZERO(&one);
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &mask)) {
      CPU_SET(c, &one);
      break;
    }
  BOOST_TEST_REQUIRE(sched_setaffinity(0, sizeof one, &one) == 0);
  BOOST_TEST(available_cpus() == 1);
  BOOST_TEST(parallel_workers() == 1);
  BOOST_TEST_REQUIRE(sched_setaffinity(0, sizeof mask, &mask) == 0);

  set_thread_budget(1);
  BOOST_TEST(std::string(std::getenv("COOLINGGEN_THREADS")) == "1");  // the processes it starts inherit it
  BOOST_TEST(parallel_workers() == 1);
  set_thread_budget(cpus + 3);
  BOOST_TEST(parallel_workers() == cpus);
  for (const char* bad : {"0", "-2", "two", "2.5", "1025", " 2"}) {
    setenv("COOLINGGEN_THREADS", bad, 1);
    BOOST_TEST(thread_budget() == -1, bad);
    BOOST_TEST(parallel_workers() == cpus, bad);
  }
  unsetenv("COOLINGGEN_THREADS");
}

namespace {
// What the future's get() throws ("" when it returns).
template <class Future>
std::string error_of(Future& f) {
  try {
    f.get();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// The calling thread's nice value (Linux: per thread).
int thread_nice() {
  return getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
}
}  // namespace

BOOST_AUTO_TEST_CASE(background_work_returns_its_result_at_the_lowest_priority) {
  unsetenv("COOLINGGEN_THREADS");
  BOOST_TEST_REQUIRE(parallel_workers() > 1, "one CPU: the work would run in the caller (next test case)");
  const int caller = thread_nice();
  // The value, and the priority the work ran at (and the threads it starts inherit).
  auto f = start_in_background([] {
    int inner = -100;
    std::thread t([&] { inner = thread_nice(); });
    t.join();
    return std::make_pair(thread_nice(), inner);
  });
  const auto [nice, inner] = f.get();
  BOOST_TEST(nice == 19);
  BOOST_TEST(inner == 19);
  BOOST_TEST(thread_nice() == caller);  // only the background thread was lowered
  // Its exception comes out of get().
  auto g = start_in_background([]() -> int { throw std::runtime_error("background failure"); });
  BOOST_TEST(error_of(g) == "background failure");
}

// On one worker (--threads 1) the work runs in the caller when first waited for, at its priority.
BOOST_AUTO_TEST_CASE(background_work_on_one_thread_runs_when_waited_for) {
  set_thread_budget(1);
  const std::thread::id caller = std::this_thread::get_id();
  bool ran = false;
  auto f = start_in_background([&] {
    ran = true;
    return std::make_pair(std::this_thread::get_id(), thread_nice());
  });
  BOOST_TEST(!ran);
  const auto [id, nice] = f.get();
  BOOST_TEST((id == caller));
  BOOST_TEST(nice == thread_nice());
  auto g = start_in_background([]() -> int { throw std::runtime_error("failure in the caller"); });
  BOOST_TEST(error_of(g) == "failure in the caller");
  unsetenv("COOLINGGEN_THREADS");
}
