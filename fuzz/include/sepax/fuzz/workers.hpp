// sepax/fuzz/workers.hpp
//
// Parallel campaigns.  Case `index` of a campaign is a pure function of the
// campaign's seed, its family list and the index (run_case): the family is
// families[index % families.size()], the generator seed case_seed(seed, index)
// (random.hpp).  run_in_order runs indices 0, 1, 2, ... on `jobs` worker
// threads and hands every outcome to the calling thread in index order, so
// whatever merges the outcomes (Report::add, reproducers, shrinking) sees the
// same sequence for any number of workers: a campaign of N cases gives the
// same report with 1 or 16 workers (apart from its timings).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <sepax/fuzz/case.hpp>
#include <sepax/fuzz/check.hpp>

namespace sepax::fuzz {

struct CaseOutcome {
  std::uint64_t index = 0;
  std::string family;
  FuzzCase c;
  CaseReport r;
};

/// The number of worker threads `jobs` asks for: jobs itself when positive,
/// otherwise every core (std::thread::hardware_concurrency, at least 1).
int worker_count(int jobs);

/// Generate and check case `index` of a campaign.  Never throws: invalid
/// shapes are a rejected case, any other exception an "internal_error"
/// finding (as check_case_guarded).
CaseOutcome run_case(const std::vector<std::string>& families, std::uint64_t campaign_seed,
                     std::uint64_t index, const CheckOptions& opt = {});

/// Run indices 0, 1, 2, ... while more(index) is true (called by the workers
/// before they take an index; indices are taken in increasing order, so the
/// indices run are 0 .. K-1 for the first K with more(K) false), each with
/// run(index) on one of worker_count(jobs) threads, and call consume(outcome)
/// on the calling thread for every index in increasing order.  At most a
/// bounded window of outcomes waits for consumption.  An exception thrown by
/// run or consume stops the workers and is rethrown here.
void run_in_order(int jobs, const std::function<bool(std::uint64_t)>& more,
                  const std::function<CaseOutcome(std::uint64_t)>& run,
                  const std::function<void(CaseOutcome&&)>& consume);

}  // namespace sepax::fuzz
