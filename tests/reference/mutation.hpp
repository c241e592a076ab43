// Test-only faults in the proof steps (reference/proof_steps.hpp): a step that always or never
// proves, an off-by-one lobe frame, a wrong sign, a lost symmetry. tests/test_mutations.cpp
// switches each on in turn and shows that the tests catch it, so a green suite says the proof
// steps are exercised, not merely run. Nothing outside that test sets one; when none is active
// each step pays one relaxed atomic load.
#pragma once

namespace gyrores::proof {

enum class mutation {
  none,
  root_always,      // certify_root returns a box around the guess without proof
  root_never,       // certify_root never proves
  basin_always,     // certify_basin accepts any Y
  basin_never,      // certify_basin never proves
  exclude_always,   // exclude_lobe excludes every lobe without looking
  exclude_never,    // exclude_lobe never excludes
  theta_off_by_one, // theta_of places U in lobe k + 1
  f_sign_flip,      // f_of returns -f (its derivative df_of unchanged)
  images_no_mirror  // images_of forgets the mirror theta -> 2 pi - theta of the minimiser
};

mutation active_mutation();

// Sets a mutation for its lifetime (tests only; not thread-safe against concurrent proofs).
class scoped_mutation {
 public:
  explicit scoped_mutation(mutation m);
  ~scoped_mutation();
  scoped_mutation(const scoped_mutation&) = delete;
  scoped_mutation& operator=(const scoped_mutation&) = delete;

 private:
  mutation previous_;
};

}  // namespace gyrores::proof
