// The cover obligation of a certificate: R/v^2 > bound everywhere on [0, 2 pi) outside the
// basins of the minimisers, decided lobe by lobe by proof::exclude_lobe (proof_steps.hpp).
// Shared by the producer (certify.hpp), the checker (check.hpp) and proofs/verify_degenerate.cpp
// (with bound 0: R has no zero outside the basins). proofs/global-minimality.md, sections 6-7.
//
// Two strategies:
//   "all-lobes"   every fast lobe k = 0 .. a-1 in the frame of its nearest slow node (order a up
//                 to certify_options::max_lobes when the strategy is chosen here);
//   "slow-nodes"  for x < 1/2 only: the Rayleigh bound with cut-off w1 = t x excludes every theta
//                 with |cos beta| >= sin w1, and the few lobes around each of the b slow nodes are
//                 bisected (b up to certify_options::max_nodes when chosen here).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "reference/certificate.hpp"
#include "reference/proof_steps.hpp"

namespace gyrores::proof {

// Basins (u-intervals) per lobe index k mod a.
using basin_map = std::map<big_int, std::vector<I>>;

// The basins of all minimiser images: Y in each image's lobe, negated for mirrored images.
basin_map basins_by_lobe(const constants& K, const std::vector<image>& images, const I& Y);

struct cover_result {
  bool proved = false;
  std::string strategy;    // the strategy run ("" when none could be chosen)
  std::string note;        // why not proved (one line; empty when proved)
  std::string rayleigh_t;  // "slow-nodes": the Rayleigh parameter t used, 6 digits
  cover_stats stats;
};

// Proves R/v^2 > bound outside the basins, at the current precision. strategy "" chooses
// ("slow-nodes" if x < 1/2 and b <= opt.max_nodes, else "all-lobes" if a <= opt.max_lobes,
// else not proved) and finds t by doubling from 1; otherwise the given strategy is run as is,
// with t read from t_text ("" means 1) and never changed (the checker re-runs the producer's
// choice). Never throws for a bad strategy or t: the result says "not proved" and why.
cover_result run_cover(const constants& K, const basin_map& basins, const I& bound,
                       const certify_options& opt, const std::string& strategy, const std::string& t_text);

}  // namespace gyrores::proof
