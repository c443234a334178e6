// SPDX-License-Identifier: MIT
// The correction-mode table (core/correction_modes.*) against what the docs and the RTL state
// independently: the three modes and their IDs, names and degree limits as docs/datapath.md gives
// them; the basis of each, enumerated here by brute force, in the register map's order
// (DatapathConfig::term2d) and of the size terms() gives; the tops that build each
// (validate(DatapathTop)); and an ID or a name no row has is an InputError that names it, in the
// table and in validate().
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "core/correction_modes.hpp"
#include "core/datapath_config.hpp"
#include "core/errors.hpp"

namespace acore {
namespace {

// The modes as docs/datapath.md "Correction modes" and the image header contract state them.
struct Spec {
  int id;
  const char* name;
  int degree_min, degree_max;
  bool folded, serial;
};
const Spec kSpec[] = {{0, "poly", 1, 7, true, true},
                      {1, "poly2d", 1, 3, false, false},
                      {2, "none", 1, 7, true, false}};

TEST(CorrectionModes, RowsAreTheDocumentedModesInIdOrder) {
  const auto& rows = correction_modes();
  ASSERT_EQ(rows.size(), std::size(kSpec));
  std::set<std::string> names;
  for (size_t i = 0; i < rows.size(); ++i) {
    const CorrectionMode& m = rows[i];
    EXPECT_EQ(m.id, static_cast<int>(i));
    EXPECT_EQ(m.id, kSpec[i].id);
    EXPECT_STREQ(m.name, kSpec[i].name);
    EXPECT_EQ(m.degree_min, kSpec[i].degree_min) << m.name;
    EXPECT_EQ(m.degree_max, kSpec[i].degree_max) << m.name;
    EXPECT_EQ(m.runs_on(kEngineFolded), kSpec[i].folded) << m.name;
    EXPECT_EQ(m.runs_on(kEngineSerial), kSpec[i].serial) << m.name;
    EXPECT_TRUE(m.runs_on(kEngineModel | kEnginePipelined)) << m.name;
    EXPECT_TRUE(names.insert(m.name).second) << "duplicate name " << m.name;
    EXPECT_EQ(&correction_mode(m.id), &m);
    EXPECT_EQ(&correction_mode(std::string(m.name)), &m);
    EXPECT_EQ(parse_correction(m.name), m.id);
    EXPECT_EQ(correction_name(m.id), m.name);
  }
  EXPECT_EQ(kPoly, 0);
  EXPECT_EQ(kPoly2d, 1);
  EXPECT_EQ(kNone, 2);
  EXPECT_EQ(correction_mode(kPoly2d).rtl_constant(), "ACORE_CORR_POLY2D");
  EXPECT_EQ(correction_mode_list(), "0 (poly), 1 (poly2d) or 2 (none)");
  EXPECT_EQ(correction_mode_list(kEngineFolded), "0 (poly) or 2 (none)");
  EXPECT_EQ(correction_mode_list(kEngineSerial), "0 (poly)");
  EXPECT_EQ(correction_mode_names(), "poly, poly2d, none");
}

// Every (i, j) with i + j <= d in the map's order for two arguments, every j <= d for one.
std::vector<std::vector<int>> brute_force_basis(int args, int degree) {
  std::vector<std::vector<int>> out;
  if (args == 1)
    for (int j = 0; j <= degree; ++j) out.push_back({j});
  if (args == 2) {
    DatapathConfig c;
    c.degree = degree;
    out.resize(static_cast<size_t>((degree + 1) * (degree + 2) / 2));
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; i + j <= degree; ++j) out.at(static_cast<size_t>(c.term2d(i, j))) = {i, j};
  }
  return out;
}

TEST(CorrectionModes, BasisIsEveryMonomialInTheMapsOrderAndTermsItsSize) {
  for (const CorrectionMode& m : correction_modes())
    for (int d = 0; d <= 7; ++d) {
      const auto powers = m.basis_powers(d);
      EXPECT_EQ(powers, brute_force_basis(m.args, d)) << m.name << " degree " << d;
      EXPECT_EQ(m.terms(d), static_cast<int>(powers.size())) << m.name << " degree " << d;
    }
  // The documented counts: n + 1, (d + 1)(d + 2) / 2, 0.
  EXPECT_EQ(correction_mode(kPoly).terms(3), 4);
  EXPECT_EQ(correction_mode(kPoly).terms(7), 8);
  EXPECT_EQ(correction_mode(kPoly2d).terms(3), 10);
  EXPECT_EQ(correction_mode(kPoly2d).terms(1), 3);
  EXPECT_EQ(correction_mode(kNone).terms(5), 0);
  DatapathConfig c;
  c.correction = kPoly2d;
  EXPECT_EQ(c.coef_per_curve(), 10);
  EXPECT_EQ(c.words(), 4 + 2 * 4 * 10 + 16);
}

TEST(CorrectionModes, AnIdOrNameOutsideTheTableIsAnInputErrorNamingIt) {
  for (int id : {-1, 3, 7, 1000}) {
    EXPECT_EQ(find_correction_mode(id), nullptr);
    try {
      correction_mode(id);
      ADD_FAILURE() << "no error for " << id;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("correction mode " + std::to_string(id)),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("0 (poly), 1 (poly2d) or 2 (none)"), std::string::npos);
    }
    DatapathConfig c;
    c.correction = id;
    try {
      c.validate();
      ADD_FAILURE() << "validate() took correction=" << id;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("correction=" + std::to_string(id) + " must be"),
                std::string::npos)
          << e.what();
    }
    EXPECT_THROW(c.coef_per_curve(), InputError);
    EXPECT_EQ(correction_name(id), std::to_string(id));  // describe() shows what it was given
  }
  try {
    parse_correction("cubic");
    ADD_FAILURE() << "no error for 'cubic'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'cubic' is not one of poly, poly2d, none"),
              std::string::npos)
        << e.what();
  }
}

TEST(CorrectionModes, ValidateTakesEachModesDegreesAndTopsAsDocumented) {
  for (const Spec& s : kSpec)
    for (int d = 0; d <= 9; ++d) {
      DatapathConfig c;
      c.correction = s.id;
      c.degree = d;
      const bool legal = d >= s.degree_min && d <= s.degree_max;
      if (legal) {
        EXPECT_NO_THROW(c.validate()) << s.name << " degree " << d;
      } else {
        try {
          c.validate();
          ADD_FAILURE() << s.name << " degree " << d << " accepted";
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find(std::string("for ") + s.name), std::string::npos)
              << e.what();
        }
      }
      if (!legal) continue;
      c.fold = 4;
      if (s.folded)
        EXPECT_NO_THROW(c.validate()) << s.name << " folded";
      else
        EXPECT_THROW(c.validate(), InputError) << s.name << " folded";
      c.fold = 1;
      if (s.serial)
        EXPECT_NO_THROW(c.validate(DatapathTop::kSerial)) << s.name << " serial";
      else
        EXPECT_THROW(c.validate(DatapathTop::kSerial), InputError) << s.name << " serial";
    }
  // The serial core's options: no centred argument, no Fourier stage, not folded.
  DatapathConfig c;
  c.regions = 8;
  c.xcenter = 1;
  EXPECT_NO_THROW(c.validate());
  EXPECT_THROW(c.validate(DatapathTop::kSerial), InputError);
  c = DatapathConfig{};
  c.fourier_k = 4;
  EXPECT_NO_THROW(c.validate());
  EXPECT_THROW(c.validate(DatapathTop::kSerial), InputError);
  c = DatapathConfig{};
  c.fold = 2;
  EXPECT_NO_THROW(c.validate());
  EXPECT_THROW(c.validate(DatapathTop::kSerial), InputError);
  // The hardware multiplier on the serial core too (its one product, rtl/acore_serial_datapath.v).
  c = DatapathConfig{};
  c.mult = 1;
  EXPECT_NO_THROW(c.validate());
  EXPECT_NO_THROW(c.validate(DatapathTop::kSerial));
}

}  // namespace
}  // namespace acore
