// SPDX-License-Identifier: MIT
#include "core/correction_modes.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstring>

#include "core/errors.hpp"

namespace acore {

namespace {

// The engines index their kernel lists by ID: the rows must be in ID order from 0.
constexpr int kIds[] = {ACORE_CORRECTION_MODES(ACORE_MODE_ID)};
constexpr bool ids_in_order() {
  for (int i = 0; i < static_cast<int>(sizeof kIds / sizeof kIds[0]); ++i)
    if (kIds[i] != i) return false;
  return true;
}
static_assert(ids_in_order(), "ACORE_CORRECTION_MODES: the rows must be in ID order 0, 1, 2, ...");

// A kernel column's name (BATCH may be nullptr: "").
const char* kernel_name(const char* stringized) {
  return std::strcmp(stringized, "nullptr") == 0 ? "" : stringized;
}

}  // namespace

int CorrectionMode::terms(int degree) const {
  if (args == 0) return 0;
  long long n = 1;
  for (int k = 1; k <= args; ++k) n = n * (degree + k) / k;  // C(degree + k, k), exact each step
  return static_cast<int>(n);
}

std::vector<std::vector<int>> CorrectionMode::basis_powers(int degree) const {
  std::vector<std::vector<int>> out;
  if (args == 0) return out;
  // Every exponent tuple of total <= degree, lexicographic (the first argument's power slowest).
  std::vector<int> p(static_cast<size_t>(args), 0);
  for (;;) {
    out.push_back(p);
    int sum = 0;
    for (int e : p) sum += e;
    int k = args - 1;
    // Raise the last power that can rise; reset the ones after it.
    while (k >= 0 && sum >= degree) {
      sum -= p[static_cast<size_t>(k)];
      p[static_cast<size_t>(k)] = 0;
      --k;
    }
    if (k < 0) return out;
    ++p[static_cast<size_t>(k)];
  }
}

const char* CorrectionMode::degree_word() const {
  return args == 0 ? "" : args == 1 ? "degree" : "total degree";
}

std::string CorrectionMode::rtl_constant() const {
  std::string s = "ACORE_CORR_";
  for (const char* c = name; *c; ++c) s += static_cast<char>(std::toupper(*c));
  return s;
}

const std::vector<CorrectionMode>& correction_modes() {
#define ACORE_MODE_ROW(ID, CONSTANT, NAME, ARGS, DMIN, DMAX, ENGINES, STAGE, LAT, FIXED, VALUE, \
                       BASIS, BATCH, MEANING, BASIS_TEXT)                                       \
  {ID,      NAME,      ARGS,   DMIN,   DMAX,   ENGINES,                                         \
   STAGE,   LAT,       #FIXED, #VALUE, #BASIS, kernel_name(#BATCH),                             \
   MEANING, BASIS_TEXT},
  static const std::vector<CorrectionMode> rows = {ACORE_CORRECTION_MODES(ACORE_MODE_ROW)};
#undef ACORE_MODE_ROW
  return rows;
}

const CorrectionMode* find_correction_mode(int id) {
  const auto& rows = correction_modes();
  return id >= 0 && id < static_cast<int>(rows.size()) ? &rows[static_cast<size_t>(id)] : nullptr;
}

const CorrectionMode& correction_mode(int id) {
  if (const CorrectionMode* m = find_correction_mode(id)) return *m;
  throw InputError(fmt::format("correction mode {} is not in the table of modes (it has {})", id,
                               correction_mode_list()));
}

const CorrectionMode& correction_mode(const std::string& name) {
  for (const CorrectionMode& m : correction_modes())
    if (name == m.name) return m;
  throw InputError(fmt::format("correction '{}' is not one of {}", name, correction_mode_names()));
}

std::string correction_mode_list(unsigned engines) {
  std::vector<std::string> items;
  for (const CorrectionMode& m : correction_modes())
    if (m.runs_on(engines)) items.push_back(fmt::format("{} ({})", m.id, m.name));
  std::string s;
  for (size_t i = 0; i < items.size(); ++i)
    s += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
  return s;
}

std::string correction_mode_names() {
  std::string s;
  for (const CorrectionMode& m : correction_modes())
    s += (s.empty() ? "" : ", ") + std::string(m.name);
  return s;
}

}  // namespace acore
