// The independent checker of certificates (certificate.hpp): check_certificate.
//
// It re-derives every obligation from the pair and the proof parameters the certificate states
// (working and cover bits, the basin Y, the cover strategy, the Rayleigh t), never from the
// producer's numbers, and accepts only if each claim contains the checker's own enclosure, meets
// the stated digits, and every required obligation is present (proofs/global-minimality.md).
#pragma once
#include "reference/certificate.hpp"

namespace gyrores {

// Re-proves a certificate. Returns a failing verdict, naming the first claim or obligation that
// does not hold, for anything false or unproved. Throws usage_error for malformed content
// (unparsable numbers, a missing field of an obligation), and compute_error when the checker's
// own enclosures cannot be computed (the certificate is then not re-proved). opt.max_bits
// bounds the precisions the certificate may ask for; the cover is re-run without the
// producer's max_lobes limit.
check_verdict check_certificate(const certificate& c, const certify_options& opt = {});

}  // namespace gyrores
