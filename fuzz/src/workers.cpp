// Parallel campaigns: see sepax/fuzz/workers.hpp.
#include <sepax/fuzz/workers.hpp>

#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#include <sepax/error.hpp>
#include <sepax/fuzz/generators.hpp>
#include <sepax/fuzz/random.hpp>

namespace sepax::fuzz {

int worker_count(int jobs) {
  if (jobs > 0) return jobs;
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

CaseOutcome run_case(const std::vector<std::string>& families, std::uint64_t campaign_seed,
                     std::uint64_t index, const CheckOptions& opt) {
  CaseOutcome o;
  o.index = index;
  o.family = families[static_cast<std::size_t>(index % families.size())];
  // The case's family and seed first: when generate itself fails, the
  // reproducer (with no shapes) still names the call that failed,
  // generate(family, seed).
  o.c.family = o.family;
  o.c.seed = case_seed(campaign_seed, index);
  try {
    o.c = generate(o.family, o.c.seed);
    o.r = check_case_guarded(o.c, opt);
  } catch (const InvalidInput& e) {
    o.r = CaseReport{};
    o.r.valid = false;
    o.r.reject_reason = e.what();
  } catch (const std::exception& e) {
    // Not bad input: a library component failed (e.g. the hull builder's
    // logic_error).  A finding, like an unexplained disagreement.
    o.r = CaseReport{};
    o.r.valid = true;
    o.r.by_comparison["internal_error"].add(Classification::unexplained);
    o.r.by_config["internal_error/" + o.family].add(Classification::unexplained);
    o.r.unexplained.push_back({"internal_error", o.family, "-", e.what()});
    o.r.unexplained_count = 1;
  }
  return o;
}

void run_in_order(int jobs, const std::function<bool(std::uint64_t)>& more,
                  const std::function<CaseOutcome(std::uint64_t)>& run,
                  const std::function<void(CaseOutcome&&)>& consume) {
  const int n = worker_count(jobs);
  if (n == 1) {
    for (std::uint64_t i = 0; more(i); ++i) consume(run(i));
    return;
  }
  std::mutex m;
  std::condition_variable ready, space;
  std::map<std::uint64_t, CaseOutcome> done;  // finished, not yet consumed
  std::uint64_t next_take = 0, next_consume = 0, end = 0;
  bool stopped = false, abort = false;
  std::exception_ptr error;
  // Outcomes waiting for the consumer (e.g. while it shrinks a finding) are
  // bounded: a worker takes index i only when i < next_consume + window.
  const std::uint64_t window = 4 * static_cast<std::uint64_t>(n) + 16;
  auto fail = [&](std::exception_ptr e) {  // with m locked
    if (!error) error = std::move(e);
    abort = true;
    ready.notify_all();
    space.notify_all();
  };
  auto worker = [&] {
    for (;;) {
      std::uint64_t i = 0;
      {
        std::unique_lock lk(m);
        space.wait(lk, [&] { return abort || stopped || next_take < next_consume + window; });
        if (abort || stopped) return;
        i = next_take;
        // Decided under the lock, in index order: the indices run are exactly
        // 0 .. end-1.
        bool go = false;
        try {
          go = more(i);
        } catch (...) {
          fail(std::current_exception());
          return;
        }
        if (!go) {
          stopped = true;
          end = i;
          ready.notify_all();
          space.notify_all();
          return;
        }
        ++next_take;
      }
      try {
        CaseOutcome o = run(i);
        std::lock_guard lk(m);
        done.emplace(i, std::move(o));
        ready.notify_all();
      } catch (...) {
        std::lock_guard lk(m);
        fail(std::current_exception());
        return;
      }
    }
  };
  std::vector<std::thread> threads;
  threads.reserve(static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t) threads.emplace_back(worker);
  {
    std::unique_lock lk(m);
    for (;;) {
      ready.wait(lk,
                 [&] { return abort || done.count(next_consume) != 0 || (stopped && next_consume >= end); });
      if (abort || (stopped && next_consume >= end && done.count(next_consume) == 0)) break;
      auto node = done.extract(next_consume);
      lk.unlock();
      try {
        consume(std::move(node.mapped()));
      } catch (...) {
        lk.lock();
        fail(std::current_exception());
        break;
      }
      lk.lock();
      ++next_consume;
      space.notify_all();
    }
  }
  for (auto& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace sepax::fuzz
