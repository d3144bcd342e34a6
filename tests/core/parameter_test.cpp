// Declared tunables: how a value is checked against its declaration, read from text and described.

#include "tandem/core/parameter.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tandem {
namespace {

using ::testing::Optional;

ParamSpec real_in(double lo, double hi, bool open = false) {
  ParamSpec s;
  s.name = "x";
  s.kind = ParamKind::real;
  s.min = lo;
  s.max = hi;
  s.min_open = open;
  return s;
}

TEST(ParamFault, RealsMustBeFiniteAndInRange) {
  const ParamSpec s = real_in(0, 1);
  EXPECT_EQ(param_fault(s, 0.0), std::nullopt);
  EXPECT_EQ(param_fault(s, 1.0), std::nullopt);
  EXPECT_EQ(param_fault(s, std::int64_t{1}), std::nullopt);
  EXPECT_THAT(param_fault(s, -0.001),
              Optional(std::string("must be a number in [0, 1], not -0.001")));
  EXPECT_THAT(param_fault(s, 1.5), Optional(std::string("must be a number in [0, 1], not 1.5")));
  EXPECT_THAT(param_fault(s, std::nan("")),
              Optional(std::string("must be a number in [0, 1], not nan")));
  EXPECT_THAT(param_fault(s, std::numeric_limits<double>::infinity()),
              Optional(std::string("must be a number in [0, 1], not inf")));
  EXPECT_THAT(param_fault(s, std::string("high")),
              Optional(std::string("must be a number in [0, 1], not 'high'")));
  EXPECT_THAT(param_fault(s, true),
              Optional(std::string("must be a number in [0, 1], not 'true'")));
}

TEST(ParamFault, OpenAndUnboundedRanges) {
  const double inf = std::numeric_limits<double>::infinity();
  const ParamSpec positive = real_in(0, inf, true);
  EXPECT_THAT(param_fault(positive, 0.0), Optional(std::string("must be a number above 0, not 0")));
  EXPECT_EQ(param_fault(positive, 1e300), std::nullopt);
  EXPECT_THAT(param_fault(positive, inf),
              Optional(std::string("must be a number above 0, not inf")));
  const ParamSpec any = real_in(-inf, inf);
  EXPECT_EQ(param_fault(any, -1e300), std::nullopt);
  EXPECT_THAT(param_fault(any, -inf), Optional(std::string("must be a finite number, not -inf")));
}

TEST(ParamFault, IntegersMustBeWhole) {
  ParamSpec s = real_in(1, 1000);
  s.kind = ParamKind::integer;
  EXPECT_EQ(param_fault(s, std::int64_t{1}), std::nullopt);
  EXPECT_EQ(param_fault(s, 1000.0), std::nullopt);  // a whole real, e.g. from JSON
  EXPECT_THAT(param_fault(s, 2.5),
              Optional(std::string("must be a whole number in [1, 1000], not 2.5")));
  EXPECT_THAT(param_fault(s, std::int64_t{0}),
              Optional(std::string("must be a whole number in [1, 1000], not 0")));
  EXPECT_EQ(std::get<std::int64_t>(normalise_param(s, 7.0)), 7);
}

TEST(ParamFault, ChoicesBooleansAndText) {
  ParamSpec c;
  c.kind = ParamKind::choice;
  c.choices = {"mag", "path"};
  EXPECT_EQ(param_fault(c, std::string("path")), std::nullopt);
  EXPECT_THAT(param_fault(c, std::string("wide")),
              Optional(std::string("must be one of mag, path, not 'wide'")));
  EXPECT_THAT(param_fault(c, 1.0), Optional(std::string("must be one of mag, path, not '1'")));
  ParamSpec b;
  b.kind = ParamKind::boolean;
  EXPECT_EQ(param_fault(b, false), std::nullopt);
  EXPECT_THAT(param_fault(b, std::string("yes")),
              Optional(std::string("must be true or false, not 'yes'")));
  ParamSpec t;
  t.kind = ParamKind::text;
  EXPECT_EQ(param_fault(t, std::string("anything")), std::nullopt);
  EXPECT_TRUE(param_fault(t, 3.0).has_value());
}

TEST(ParseParamText, ReadsWhatTheKindMeansAndRefusesTheRest) {
  const ParamSpec s = real_in(0, 1);
  EXPECT_DOUBLE_EQ(std::get<double>(std::get<ParamValue>(parse_param_text(s, "0.25"))), 0.25);
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "1e999", "0.5x", "", " 0.5", "0x1p-1z"})
    EXPECT_TRUE(std::holds_alternative<std::string>(parse_param_text(s, bad))) << bad;
  ParamSpec i = real_in(1, 10);
  i.kind = ParamKind::integer;
  EXPECT_EQ(std::get<std::int64_t>(std::get<ParamValue>(parse_param_text(i, "10"))), 10);
  EXPECT_EQ(std::get<std::string>(parse_param_text(i, "3.5")),
            "must be a whole number in [1, 10], not 3.5");
  ParamSpec b;
  b.kind = ParamKind::boolean;
  for (const char* yes : {"true", "on", "1"})
    EXPECT_TRUE(std::get<bool>(std::get<ParamValue>(parse_param_text(b, yes))));
  for (const char* no : {"false", "off", "0"})
    EXPECT_FALSE(std::get<bool>(std::get<ParamValue>(parse_param_text(b, no))));
  EXPECT_EQ(std::get<std::string>(parse_param_text(b, "maybe")),
            "must be true or false, not 'maybe'");
}

TEST(ParamSpec, OptionNamesAndFormats) {
  ParamSpec s;
  s.name = "contact_samples";
  EXPECT_EQ(s.option(), "--contact-samples");
  EXPECT_EQ(format_param(0.5), "0.5");
  EXPECT_EQ(format_param(std::int64_t{12}), "12");
  EXPECT_EQ(format_param(true), "true");
}

}  // namespace
}  // namespace tandem
