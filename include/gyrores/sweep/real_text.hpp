// Reals of a sweep as text, the form rows and summaries hold (docs/formats.md, sweep rows):
// doubles in the shortest form that reads back exactly (std::to_chars), wider types with
// `digits` (at least 17) significant digits, correctly rounded (core/decimal.hpp; an mpfr_real
// is printed from its own bits, at its own precision). Summaries
// compare and sort values as the doubles these texts read back to, so that a single run and a
// merge of its rows agree bit for bit.
#pragma once
#include <string>
#include <type_traits>

#include <gyrores/core/decimal.hpp>

namespace gyrores {

// Shortest decimal text that reads back to v exactly.
std::string sweep_double_text(double v);

// v as rows print it: sweep_double_text for double, else max(digits, 17) significant digits.
template <class T> std::string sweep_real_text(const T& v, unsigned digits) {
  if constexpr (std::is_same_v<T, double>) return sweep_double_text(v);
  else if constexpr (is_mpfr_v<T>) return format_scientific(v.backend().data(), digits < 17 ? 17 : digits);
  else return format_scientific(real_to_mpfr(v), digits < 17 ? 17 : digits);
}

// Text to double, correctly rounded; compute_error on text that is not a whole real number.
double sweep_text_double(const std::string& s);

// Compiled once in src/lib/sweep/real_text.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_REAL_TEXT_INSTANCES(PREFIX, T) PREFIX template std::string sweep_real_text<T>(const T&, unsigned);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_REAL_TEXT_INSTANCES, extern)

}  // namespace gyrores
