// SPDX-License-Identifier: MIT
// Recording file I/O (docs/contracts.md, recording file). The parser works on string_views over the
// whole file and converts numbers with std::from_chars, so a million-row recording parses in well
// under a second.
#include "core/recording.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string_view>

#include "core/errors.hpp"

namespace acore {

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && (blank(s.back()) || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Splits one line on commas (no quoting: the format has numbers and plain names only).
void split(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  size_t start = 0;
  for (;;) {
    const size_t comma = line.find(',', start);
    const size_t len = comma == std::string_view::npos ? std::string_view::npos : comma - start;
    out.push_back(trim(line.substr(start, len)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
}

// The whole (trimmed) field must be one finite decimal number; a leading '+' is accepted.
// Returns an empty string on success, else what is wrong.
const char* parse_number(std::string_view f, double& v) {
  if (f.empty()) return "empty field, expected a number";
  std::string_view body = f;
  if (body.front() == '+') body.remove_prefix(1);
  if (body.empty() || body.front() == '+' || (body.size() < f.size() && body.front() == '-'))
    return "not a number";
  const auto res =
      std::from_chars(body.data(), body.data() + body.size(), v, std::chars_format::general);
  if (res.ec == std::errc::result_out_of_range) return "out of the range of a double";
  if (res.ec != std::errc() || res.ptr != body.data() + body.size()) return "not a number";
  if (!std::isfinite(v)) return "NaN or infinite value";
  return "";
}

}  // namespace

void Recording::check_consistent(const std::string& what) const {
  const size_t n = size();
  auto check = [&](const std::vector<double>& v, const std::string& name) {
    if (!v.empty() && v.size() != n)
      throw InputError(
          fmt::format("{}: column '{}' has {} samples, the channels {}", what, name, v.size(), n));
  };
  for (int c = 1; c < channels; ++c) {
    if (ch[static_cast<size_t>(c)].size() != n)
      throw InputError(fmt::format("{}: channel {} has {} samples, channel 1 has {}", what, c + 1,
                                   ch[static_cast<size_t>(c)].size(), n));
  }
  check(theta_ref, "theta_ref");
  check(t, "t");
  check(temp, "temp");
}

int turn_sectors_covered(const std::vector<double>& theta, int periodicity) {
  std::array<bool, 36> seen{};
  for (double th : theta) {
    double e = std::fmod(periodicity * th, 2 * M_PI);
    if (e < 0) e += 2 * M_PI;
    seen[std::min(35, static_cast<int>(e / (2 * M_PI) * 36))] = true;
  }
  return static_cast<int>(std::count(seen.begin(), seen.end(), true));
}

Recording parse_recording(const std::string& text, const std::string& name) {
  Recording rec;
  const std::string_view all(text);
  size_t pos = 0, lineno = 0;
  auto next_line = [&](std::string_view& line) {
    if (pos >= all.size()) return false;
    size_t end = all.find('\n', pos);
    if (end == std::string_view::npos) end = all.size();
    line = all.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = end + 1;
    ++lineno;
    return true;
  };
  std::string_view line;
  // Leading comment lines: `# key=value` metadata (key without blanks) or free text.
  bool have_header = false;
  while (next_line(line)) {
    const std::string_view tl = trim(line);
    if (tl.empty()) continue;
    if (tl.front() == '#') {
      const std::string_view body = trim(tl.substr(1));
      const size_t eq = body.find('=');
      const std::string_view key =
          eq == std::string_view::npos ? std::string_view() : trim(body.substr(0, eq));
      if (!key.empty() && key.find_first_of(" \t") == std::string_view::npos)
        rec.meta[std::string(key)] = std::string(trim(body.substr(eq + 1)));
      else
        rec.comments.emplace_back(body);
      continue;
    }
    have_header = true;
    break;
  }
  if (!have_header)
    throw InputError(
        fmt::format("{}:{}: empty file: no header row (expected theta_ref,c1,c2,c3,c4 or sin,cos)",
                    name, lineno + 1));
  const size_t header_line = lineno;
  std::vector<std::string_view> fields;
  split(line, fields);
  const std::vector<std::string> names(fields.begin(), fields.end());
  for (size_t k = 0; k < names.size(); ++k) {
    if (names[k].empty())
      throw InputError(fmt::format("{}:{}: column {}: empty column name in the header", name,
                                   header_line, k + 1));
    for (size_t j = 0; j < k; ++j)
      if (names[j] == names[k])
        throw InputError(
            fmt::format("{}:{}: column '{}': appears twice in the header (columns {} and {})", name,
                        header_line, names[k], j + 1, k + 1));
  }
  // Column index per known name, -1 when absent.
  auto find = [&](const char* col) {
    for (size_t k = 0; k < names.size(); ++k)
      if (names[k] == col) return static_cast<int>(k);
    return -1;
  };
  const int i_c[4] = {find("c1"), find("c2"), find("c3"), find("c4")};
  const int i_sin = find("sin"), i_cos = find("cos");
  const int i_theta = find("theta_ref"), i_t = find("t"), i_temp = find("temp");
  const bool any4 = i_c[0] >= 0 || i_c[1] >= 0 || i_c[2] >= 0 || i_c[3] >= 0;
  const bool any2 = i_sin >= 0 || i_cos >= 0;
  if (any4 && any2)
    throw InputError(fmt::format(
        "{}:{}: column '{}': the header has both c1..c4 and sin,cos columns: use one set", name,
        header_line, i_sin >= 0 ? "sin" : "cos"));
  // (column index, destination); the channel columns come first.
  std::vector<std::pair<size_t, std::vector<double>*>> cols;
  if (any2) {
    rec.channels = 2;
    if (i_sin < 0)
      throw InputError(
          fmt::format("{}:{}: column 'sin': missing (a two-channel recording needs sin and cos)",
                      name, header_line));
    if (i_cos < 0)
      throw InputError(
          fmt::format("{}:{}: column 'cos': missing (a two-channel recording needs sin and cos)",
                      name, header_line));
    cols = {{static_cast<size_t>(i_sin), &rec.ch[0]}, {static_cast<size_t>(i_cos), &rec.ch[1]}};
  } else {
    rec.channels = 4;
    for (size_t c = 0; c < 4; ++c) {
      if (i_c[c] < 0)
        throw InputError(fmt::format("{}:{}: column 'c{}': missing (need c1,c2,c3,c4 or sin,cos)",
                                     name, header_line, c + 1));
      cols.push_back({static_cast<size_t>(i_c[c]), &rec.ch[c]});
    }
  }
  if (i_theta >= 0) cols.push_back({static_cast<size_t>(i_theta), &rec.theta_ref});
  if (i_t >= 0) cols.push_back({static_cast<size_t>(i_t), &rec.t});
  if (i_temp >= 0) cols.push_back({static_cast<size_t>(i_temp), &rec.temp});

  // Reserve from a line-count estimate so a large file does not reallocate repeatedly.
  const std::string_view rest = all.substr(std::min(pos, all.size()));
  const size_t rows_guess = static_cast<size_t>(std::count(rest.begin(), rest.end(), '\n')) + 1;
  for (auto& c : cols) c.second->reserve(rows_guess);

  while (next_line(line)) {
    if (trim(line).empty()) continue;
    split(line, fields);
    if (fields.size() < names.size())
      throw InputError(fmt::format(
          "{}:{}: column '{}': missing field (ragged row: {} fields, the header has {})", name,
          lineno, names[fields.size()], fields.size(), names.size()));
    if (fields.size() > names.size())
      throw InputError(
          fmt::format("{}:{}: column {}: extra field beyond the header (ragged row: {} fields, the "
                      "header has {})",
                      name, lineno, names.size() + 1, fields.size(), names.size()));
    for (const auto& [idx, dest] : cols) {
      double v = 0;
      const char* err = parse_number(fields[idx], v);
      if (*err)
        throw InputError(fmt::format("{}:{}: column '{}': {}: '{}'", name, lineno, names[idx], err,
                                     std::string(fields[idx])));
      dest->push_back(v);
    }
  }
  if (rec.size() == 0)
    throw InputError(fmt::format("{}:{}: no data rows after the header", name, header_line));
  return rec;
}

Recording read_recording(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(fmt::format("{}: cannot open recording", path));
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_recording(ss.str(), path);
}

std::string format_recording(const Recording& rec) {
  std::string out;
  for (const auto& [k, v] : rec.meta) out += fmt::format("# {}={}\n", k, v);
  for (const auto& c : rec.comments) out += "# " + c + "\n";
  std::vector<std::pair<std::string, const std::vector<double>*>> cols;
  if (rec.has_t()) cols.push_back({"t", &rec.t});
  if (rec.has_theta()) cols.push_back({"theta_ref", &rec.theta_ref});
  if (rec.channels == 4) {
    for (size_t c = 0; c < 4; ++c) cols.push_back({fmt::format("c{}", c + 1), &rec.ch[c]});
  } else {
    cols.push_back({"sin", &rec.ch[0]});
    cols.push_back({"cos", &rec.ch[1]});
  }
  if (rec.has_temp()) cols.push_back({"temp", &rec.temp});
  for (size_t k = 0; k < cols.size(); ++k) out += (k ? "," : "") + cols[k].first;
  out += '\n';
  out.reserve(out.size() + rec.size() * cols.size() * 24);
  auto it = std::back_inserter(out);
  for (size_t i = 0; i < rec.size(); ++i) {
    for (size_t k = 0; k < cols.size(); ++k) {
      if (k) out += ',';
      fmt::format_to(it, "{:.17g}", (*cols[k].second)[i]);
    }
    out += '\n';
  }
  return out;
}

void write_recording(const Recording& rec, const std::string& path) {
  rec.check_consistent(path);
  std::ofstream f(path, std::ios::binary);
  if (!f) throw InputError(fmt::format("{}: cannot write recording", path));
  f << format_recording(rec);
  if (!f) throw InputError(fmt::format("{}: write failed", path));
}

int recording_periodicity(const Recording& rec, const std::string& path) {
  const auto it = rec.meta.find("p");
  if (it == rec.meta.end()) return 1;
  try {
    size_t used = 0;
    const int p = std::stoi(it->second, &used);
    if (used == it->second.size() && p >= 1 && p <= 64) return p;
  } catch (const std::exception&) {
  }
  throw InputError(path + ": metadata 'p': '" + it->second + "' is not a periodicity 1..64");
}

}  // namespace acore
