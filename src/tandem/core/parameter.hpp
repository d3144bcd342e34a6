#pragma once
// A tunable declared once: its name, the papers' symbol, unit, range, help and the planners that
// use it (OMPL's declareParam). Every surface — command-line options and their help, scenario
// `[planner]` keys, experiment keys, the viewer's protocol and tuning panel, the JSON output and
// the journal — reads the declarations and checks values with param_fault(), so that a value is
// refused the same way, with the same range, wherever it comes from.
//
// A family of tunables is a ParamTable over the settings struct that holds them; the struct's
// default member initialisers are the defaults (a table reads them from `Settings{}`).

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace tandem {

enum class ParamKind : std::uint8_t {
  real,     ///< a finite number in [min, max] (or (min, max] with min_open)
  integer,  ///< a whole number in [min, max]
  boolean,  ///< true or false (on the command line: true, false, on, off, 1, 0)
  choice,   ///< one of `choices`
  text,     ///< free text (checked by whoever uses it, e.g. an operator name)
};
std::string_view to_string(ParamKind kind);

using ParamValue = std::variant<double, std::int64_t, bool, std::string>;

/// How a value reads in a label, a report or an error ("0.5", "10", "true", "mag").
std::string format_param(const ParamValue& value);

struct ParamSpec {
  std::string_view
      name;  ///< the key in files, JSON and the protocol; the option is --name-with-dashes
  std::string_view symbol;  ///< the papers' symbol (α, N, d, σ, p, x), or empty
  std::string_view label;   ///< a few words for a user interface
  std::string_view unit;    ///< "m" for lengths in scene units, "s", or empty
  ParamKind kind = ParamKind::real;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< (min, max] instead of [min, max]
  std::vector<std::string_view> choices;
  std::string_view help;
  /// The group of tunables it belongs to ("sharing", "irrt", "operator", ...; empty: every tree
  /// planner's). Each planner of the registry lists the groups it reads.
  std::string_view group;
  /// May change while planning (the viewer's tuning panel).
  bool live = false;

  /// The command-line option: "--" and the name with '_' as '-'.
  std::string option() const;
};

/// "a number in [0, 1]", "a whole number of at least 1", "one of mag, path", ...
std::string describe_range(const ParamSpec& spec);

/// Why `value` is not a valid value of `spec` ("must be a number in [0, 1], not nan"), or nothing.
/// Integers given as whole reals (from JSON or TOML) are accepted as integers.
std::optional<std::string> param_fault(const ParamSpec& spec, const ParamValue& value);

/// The value `text` means for `spec` (command-line text), or the fault.
std::variant<ParamValue, std::string> parse_param_text(const ParamSpec& spec,
                                                       std::string_view text);

/// The value `text` means for `spec`, given on the command line as spec.option(); throws
/// InputError naming the option and the fault.
ParamValue parse_param_option(const ParamSpec& spec, std::string_view text);

/// `value` converted to the spec's kind (an integer given as a real, a real given as an integer);
/// call after param_fault() found nothing.
ParamValue normalise_param(const ParamSpec& spec, const ParamValue& value);

/// One declared tunable and where it lives in a settings struct.
template <class Settings>
struct Param {
  ParamSpec spec;
  std::function<ParamValue(const Settings&)> get;
  std::function<void(Settings&, const ParamValue&)> set;
};

template <class Settings>
using ParamTable = std::vector<Param<Settings>>;

/// The declaration named `name` in `table`, or nullptr.
template <class Settings>
const Param<Settings>* find_param(const ParamTable<Settings>& table, std::string_view name) {
  for (const auto& p : table) {
    if (p.spec.name == name)
      return &p;
  }
  return nullptr;
}

// Bindings of struct members, for the tables.
template <class Settings>
Param<Settings> real_param(ParamSpec spec, double Settings::*member) {
  spec.kind = ParamKind::real;
  return {std::move(spec), [member](const Settings& s) { return ParamValue(s.*member); },
          [member](Settings& s, const ParamValue& v) { s.*member = std::get<double>(v); }};
}

template <class Settings, class Int>
Param<Settings> integer_param(ParamSpec spec, Int Settings::*member) {
  spec.kind = ParamKind::integer;
  return {std::move(spec),
          [member](const Settings& s) { return ParamValue(static_cast<std::int64_t>(s.*member)); },
          [member](Settings& s, const ParamValue& v) {
            s.*member = static_cast<Int>(std::get<std::int64_t>(v));
          }};
}

template <class Settings>
Param<Settings> boolean_param(ParamSpec spec, bool Settings::*member) {
  spec.kind = ParamKind::boolean;
  return {std::move(spec), [member](const Settings& s) { return ParamValue(s.*member); },
          [member](Settings& s, const ParamValue& v) { s.*member = std::get<bool>(v); }};
}

/// An enum (or string) member read and written through its names; `choices` are the names.
template <class Settings, class Enum, class Name, class Parse>
Param<Settings> choice_param(ParamSpec spec, Enum Settings::*member, Name name, Parse parse) {
  spec.kind = ParamKind::choice;
  return {std::move(spec),
          [member, name](const Settings& s) { return ParamValue(std::string(name(s.*member))); },
          [member, parse](Settings& s, const ParamValue& v) {
            s.*member = *parse(std::get<std::string>(v));
          }};
}

template <class Settings>
Param<Settings> text_param(ParamSpec spec, std::string Settings::*member) {
  spec.kind = ParamKind::text;
  return {std::move(spec), [member](const Settings& s) { return ParamValue(s.*member); },
          [member](Settings& s, const ParamValue& v) { s.*member = std::get<std::string>(v); }};
}

}  // namespace tandem
