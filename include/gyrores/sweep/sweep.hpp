// Sweeps: every resonant pair with min_order <= tau + sigma <= max_order, evaluated and checked
// against the paper's claims (docs/mathematics.md §2), with a deterministic, mergeable summary.
// This header gathers the folder, one job per header:
//   checks.hpp     the checks, their names and the sweep's configuration;
//   real_text.hpp  reals as rows and summaries print them;
//   certified.hpp  one pair's proved enclosures and integer facts (the theorem, MPFI at an
//                  explicit precision): the values of every row wider than double, the proofs
//                  of --certified;
//   evaluate.hpp   one pair: its row (the exact quantities and each check's verdict);
//   filtered.hpp   a cheap filter before an exact evaluation, with its outcome counts;
//   summary.hpp    what the summary keeps of a row, the mergeable accumulator, exact quantiles;
//   count.hpp      the number of pairs of a sweep and of a shard, without enumerating them;
//   engine.hpp     sweep_run: blocks of pairs on worker threads, delivered in enumeration order.
// (testing.hpp: the internal steps the tests call, not part of this umbrella.) Files (rows,
// summary, resume state, merge) are the io/ part: io/sweep_files.hpp and its siblings, formats
// in docs/formats.md; the sweep as a request of the CLI and Python: app/sweep.hpp.
#pragma once
#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/count.hpp>
#include <gyrores/sweep/engine.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/sweep/filtered.hpp>
#include <gyrores/sweep/real_text.hpp>
#include <gyrores/sweep/summary.hpp>
