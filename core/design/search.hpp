// SPDX-License-Identifier: GPL-3.0-or-later
// Design search: the link lengths, motor spacing and rectangle placement that best meet an
// objective within a maker's bounds, and the trade-off between worst-case condition number and
// footprint (docs/design.md "Search"). NLopt: a global method (CRS2 with local mutation, seeded)
// from several starts, each followed by a local one (Subplex); starts run on all threads.
// Deterministic: the result depends on the brief and SearchOptions::seed only, not on the
// number of threads or their timing.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/design/objective.hpp"

namespace fivebar::design {

// The maker's bounds on the lengths (mm).
struct DesignBounds {
  double minLinkMm = 30.0;   // every link (a1, b1, a2, b2) at least this long
  double maxLinkMm = 200.0;  // and at most this long
  double minBaseMm = 0.0;    // motor spacing w
  double maxBaseMm = 250.0;
  bool symmetric = false;    // a1 = a2 and b1 = b2
};

struct DesignBrief {
  double widthMm = 110.0;  // target rectangle, width along x (unless allowRotation turns it)
  double heightMm = 90.0;
  DesignBounds bounds;
  DesignRules rules;
  std::optional<WorkingMode> mode;  // nullopt: search all four working modes
  Objective objective = Objective::Condition;
  MixWeights weights;               // Objective::Mix only
  bool allowRotation = false;       // also place the rectangle turned by 90 degrees
};

// Problems with the brief itself (field names like "bounds.maxLinkMm").
std::vector<ValidationIssue> validate(const DesignBrief& brief);

struct SearchOptions {
  std::uint32_t seed = 1;
  unsigned threads = 2;            // worker threads (the starts are shared among them)
  int startsPerMode = 4;           // independent global + local runs per working mode (and turn)
  int globalEvaluations = 3000;    // per start, on the coarse sampling
  int localEvaluations = 1500;     // per start, on the medium sampling
  std::size_t paretoSize = 16;     // at most this many designs in the trade-off set
  Sampling finalSampling{1.0};     // the reported evaluations
};

struct Design {
  Geometry geometry;
  WorkingMode mode = WorkingMode::PlusPlus;
  Rect rect;             // where the target rectangle sits, machine frame
  bool rotated = false;  // the rectangle's width runs along y
  Evaluation evaluation; // at SearchOptions::finalSampling
  double score = 0.0;    // penalisedScore for the brief's objective
};

struct SearchProgress {
  double fraction = 0.0;  // of the evaluation budget, [0, 1]
  long evaluations = 0;
  double bestScore = 0.0; // best penalised score seen so far (coarse sampling)
};
// Called from worker threads, never two at once.
using ProgressFn = std::function<void(const SearchProgress&)>;

enum class SearchStatus { Found, Impossible, Cancelled };

struct SearchResult {
  SearchStatus status = SearchStatus::Impossible;
  std::optional<Design> best;   // Found: the best design; Impossible: the closest miss
  std::vector<Design> pareto;   // worst-case condition number vs footprint, by footprint
  std::string binding;          // Impossible: "reach", "typeII", "typeI", "clearance", ...
  std::string message;          // Impossible: a sentence saying which constraint binds
  long evaluations = 0;
  double seconds = 0.0;
};

SearchResult searchDesigns(const DesignBrief& brief, const SearchOptions& options = {},
                           const ProgressFn& progress = {},
                           const std::atomic<bool>* cancel = nullptr);

// The rules the search optimises against: the brief's margins tightened a little, so that a
// design that keeps them on the search's coarser samplings keeps the brief's on the final one.
DesignRules searchRules(const DesignRules& rules);

}  // namespace fivebar::design
