// SPDX-License-Identifier: MIT
// The correction modes: one row per mode, and every fact about a mode is read from its row. The
// rows are ACORE_CORRECTION_MODES below, a list each layer expands for the columns it can see:
// this folder the facts (correction_modes(): names, terms, limits, engines, kernel names), the
// engines their kernels (engine/fixed_model.cpp, engine/float_model.cpp, engine/fixed_batch.cpp),
// and acore_gen_tables the RTL's constants, functions and rules (rtl/acore_modes.vh,
// rtl/acore_mode_checks.vh) and the docs' table (docs/reports/correction_modes.md). Adding a mode
// is one row here plus its kernels and its RTL stage (docs/architecture.md, "A correction mode").
#pragma once
#include <string>
#include <vector>

namespace acore {

// The engines that run a mode (the ENGINES column, a set of these bits).
enum CorrectionEngine : unsigned {
  kEngineFloat = 1u << 0,      // the float model (engine/float_model.cpp)
  kEngineFixed = 1u << 1,      // the bit-accurate model, one sample (FixedModel::step)
  kEngineBatch = 1u << 2,      // FixedModel::run_batch (its vector kernel, or step() per sample)
  kEnginePipelined = 1u << 3,  // rtl/acore_top.v with FOLD = 1
  kEngineFolded = 1u << 4,     // rtl/acore_top.v with FOLD > 1 (rtl/acore_fold_datapath.v)
  kEngineSerial = 1u << 5,     // rtl/acore_serial_top.v
};
constexpr unsigned kEngineModel = kEngineFloat | kEngineFixed | kEngineBatch;

// The rows. Columns:
//   ID         the RTL parameter CORRECTION's value; the rows are in ID order from 0
//   CONSTANT   the C++ constant of the ID (kPoly, ...)
//   NAME       the image header's and the CLI's name (`correction=poly2d`, --correction poly2d)
//   ARGS       the polynomial's arguments: 0 none, 1 u, 2 (u, v). The basis is every monomial of
//              total degree <= DEGREE in them, grouped by the power of u, then of v (the register
//              map's order); its size is the terms per region and curve, C(DEGREE + ARGS, ARGS)
//   DMIN DMAX  the legal DEGREE
//   ENGINES    the engines that run it (CorrectionEngine bits)
//   RTL_STAGE  the RTL module of the stage ("" without one) and its latency function in
//   RTL_LAT    rtl/acore_derived.vh, called (DEGREE, S_W)
//   FIXED      bit-accurate kernel, both curves of a sample (stages/correction.hpp)
//   VALUE      float kernel, P(x, y_other) of one curve in double (stages/correction.hpp)
//   BASIS      calibration kernel, the basis values at (x, y_other), what the fit solves over
//   BATCH      vector kernel of FixedModel::run_batch (engine/fixed_batch.cpp), or nullptr: the
//              batch runs step() per sample
//   MEANING    what the mode computes (docs, CLI help)
//   BASIS_TEXT the basis in words (docs)
// clang-format off
#define ACORE_CORRECTION_MODES(ROW)                                                               \
  ROW(0, kPoly, "poly", 1, 1, 7,                                                                  \
      kEngineModel | kEnginePipelined | kEngineFolded | kEngineSerial,                            \
      "acore_poly_correct", "acore_poly_latency",                                                 \
      poly_correct_curves, poly_value, poly_basis, batch_poly,                                    \
      "y = s - P(u), a polynomial of degree n in u (the paper's Eq. 6)",                          \
      "u^j, j = 0..n")                                                                            \
  ROW(1, kPoly2d, "poly2d", 2, 1, 3,                                                              \
      kEngineModel | kEnginePipelined,                                                            \
      "acore_poly2d_correct", "acore_poly2d_latency",                                             \
      poly2d_correct_curves, poly2d_value, poly2d_basis, nullptr,                                 \
      "y = s - P(u, v), a polynomial of total degree d in u and v = 4 (y_other - sign y_other)",  \
      "u^i v^j, i + j <= d")                                                                      \
  ROW(2, kNone, "none", 0, 1, 7,                                                                  \
      kEngineModel | kEnginePipelined | kEngineFolded,                                            \
      "", "",                                                                                     \
      none_correct_curves, none_value, none_basis, batch_none,                                    \
      "y = s: no polynomial words, the scaled curves go straight to the CORDIC",                  \
      "none")
// clang-format on

// Column selectors for ACORE_CORRECTION_MODES: each expands a row to one column and a comma.
#define ACORE_MODE_ID(ID, CONSTANT, NAME, ARGS, DMIN, DMAX, ENGINES, STAGE, LAT, FIXED, VALUE, \
                      BASIS, BATCH, MEANING, BASIS_TEXT)                                       \
  ID,
#define ACORE_MODE_FIXED(ID, CONSTANT, NAME, ARGS, DMIN, DMAX, ENGINES, STAGE, LAT, FIXED, VALUE, \
                         BASIS, BATCH, MEANING, BASIS_TEXT)                                       \
  FIXED,
#define ACORE_MODE_VALUE(ID, CONSTANT, NAME, ARGS, DMIN, DMAX, ENGINES, STAGE, LAT, FIXED, VALUE, \
                         BASIS, BATCH, MEANING, BASIS_TEXT)                                       \
  VALUE,
#define ACORE_MODE_BASIS(ID, CONSTANT, NAME, ARGS, DMIN, DMAX, ENGINES, STAGE, LAT, FIXED, VALUE, \
                         BASIS, BATCH, MEANING, BASIS_TEXT)                                       \
  BASIS,
#define ACORE_MODE_BATCH(ID, CONSTANT, NAME, ARGS, DMIN, DMAX, ENGINES, STAGE, LAT, FIXED, VALUE, \
                         BASIS, BATCH, MEANING, BASIS_TEXT)                                       \
  BATCH,

// The constants kPoly = 0, kPoly2d = 1, kNone = 2 (RTL CORRECTION).
#define ACORE_MODE_CONSTANT(ID, CONSTANT, NAME, ARGS, DMIN, DMAX, ENGINES, STAGE, LAT, FIXED, \
                            VALUE, BASIS, BATCH, MEANING, BASIS_TEXT)                         \
  constexpr int CONSTANT = ID;
ACORE_CORRECTION_MODES(ACORE_MODE_CONSTANT)
#undef ACORE_MODE_CONSTANT

// One row's facts (the kernels by name: the engines hold the functions).
struct CorrectionMode {
  int id;
  const char* name;
  int args;
  int degree_min, degree_max;
  unsigned engines;
  const char* rtl_stage;    // "" without a stage
  const char* rtl_latency;  // "" without a stage
  const char* fixed_kernel;
  const char* value_kernel;
  const char* basis_kernel;
  const char* batch_kernel;  // "" when the batch runs step()
  const char* meaning;
  const char* basis_text;

  bool runs_on(unsigned engine) const { return (engines & engine) == engine; }
  // Coefficients per region and curve: the basis's size, C(degree + args, args); 0 without
  // arguments (no polynomial).
  int terms(int degree) const;
  // The basis in the register map's order: term t is u^p[0] (v^p[1]) with p = powers[t].
  std::vector<std::vector<int>> basis_powers(int degree) const;
  // What DEGREE is to this mode: "degree", "total degree", or "" (unused).
  const char* degree_word() const;
  // The RTL's constant, "ACORE_CORR_POLY2D".
  std::string rtl_constant() const;
};

// Every row, in ID order.
const std::vector<CorrectionMode>& correction_modes();
// The row of an ID; throws InputError naming the ID and the table's modes when there is none.
const CorrectionMode& correction_mode(int id);
// The row of a name; throws InputError naming it and the table's names when there is none.
const CorrectionMode& correction_mode(const std::string& name);
// nullptr when no row has this ID.
const CorrectionMode* find_correction_mode(int id);
// "0 (poly), 1 (poly2d) or 2 (none)": the rows of the modes with all of `engines`.
std::string correction_mode_list(unsigned engines = 0);
// "poly, poly2d, none".
std::string correction_mode_names();

}  // namespace acore
