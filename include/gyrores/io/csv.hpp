// CSV fields and lines (RFC 4180 quoting), for the tables gyrores writes and reads back.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace gyrores {

// Appends v as one field: bare, or quoted with its quotes doubled if it holds a comma, a quote
// or a line break.
void csv_append_field(std::string& out, std::string_view v);

// The fields of one line (without its line break): RFC 4180 quoting, doubled quotes inside
// quotes. Fields holding line breaks are not supported (the line is one line of a file).
std::vector<std::string> csv_split_line(std::string_view line);

}  // namespace gyrores
