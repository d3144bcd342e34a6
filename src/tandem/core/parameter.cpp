#include "tandem/core/parameter.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "tandem/core/error.hpp"

namespace tandem {
namespace {

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string interval(const ParamSpec& s) {
  const bool low = std::isfinite(s.min), high = std::isfinite(s.max);
  if (low && high)
    return std::string(s.min_open ? "(" : "[") + number_text(s.min) + ", " + number_text(s.max) +
           "]";
  if (low)
    return std::string(s.min_open ? "above " : "at least ") + number_text(s.min);
  if (high)
    return "at most " + number_text(s.max);
  return "";
}

bool in_range(const ParamSpec& s, double v) {
  const bool above_min = s.min_open ? v > s.min : v >= s.min;
  return above_min && v <= s.max;
}

std::string fault(const ParamSpec& s, const std::string& got) {
  return "must be " + describe_range(s) + ", not " + got;
}

std::optional<std::string> number_fault(const ParamSpec& s, double v) {
  if (!std::isfinite(v) || !in_range(s, v))
    return fault(s, number_text(v));
  if (s.kind == ParamKind::integer && v != std::floor(v))
    return fault(s, number_text(v));
  return std::nullopt;
}

}  // namespace

std::string_view to_string(ParamKind kind) {
  static constexpr std::string_view kNames[] = {"real", "integer", "boolean", "choice", "text"};
  return kNames[static_cast<std::size_t>(kind)];
}

std::string format_param(const ParamValue& value) {
  if (const auto* d = std::get_if<double>(&value))
    return number_text(*d);
  if (const auto* i = std::get_if<std::int64_t>(&value))
    return std::to_string(*i);
  if (const auto* b = std::get_if<bool>(&value))
    return *b ? "true" : "false";
  return std::get<std::string>(value);
}

std::string ParamSpec::option() const {
  std::string o = "--" + std::string(name);
  std::replace(o.begin(), o.end(), '_', '-');
  return o;
}

std::string describe_range(const ParamSpec& s) {
  switch (s.kind) {
    case ParamKind::real:
    case ParamKind::integer: {
      const bool whole = s.kind == ParamKind::integer;
      const std::string r = interval(s);
      if (r.empty())
        return whole ? "a whole number" : "a finite number";
      return (whole ? "a whole number" : "a number") +
             std::string(r[0] == '[' || r[0] == '(' ? " in " : " ") + r;
    }
    case ParamKind::boolean:
      return "true or false";
    case ParamKind::choice: {
      std::string names;
      for (std::string_view c : s.choices)
        names += (names.empty() ? "" : ", ") + std::string(c);
      return "one of " + names;
    }
    case ParamKind::text:
      return "a text";
  }
  return "";
}

std::optional<std::string> param_fault(const ParamSpec& s, const ParamValue& value) {
  switch (s.kind) {
    case ParamKind::real:
    case ParamKind::integer:
      if (const auto* d = std::get_if<double>(&value))
        return number_fault(s, *d);
      if (const auto* i = std::get_if<std::int64_t>(&value))
        return number_fault(s, static_cast<double>(*i));
      return fault(s, "'" + format_param(value) + "'");
    case ParamKind::boolean:
      if (std::holds_alternative<bool>(value))
        return std::nullopt;
      return fault(s, "'" + format_param(value) + "'");
    case ParamKind::choice: {
      const auto* text = std::get_if<std::string>(&value);
      if (text != nullptr &&
          std::find(s.choices.begin(), s.choices.end(), *text) != s.choices.end())
        return std::nullopt;
      return fault(s, "'" + format_param(value) + "'");
    }
    case ParamKind::text:
      if (std::holds_alternative<std::string>(value))
        return std::nullopt;
      return fault(s, format_param(value));
  }
  return std::nullopt;
}

ParamValue parse_param_option(const ParamSpec& spec, std::string_view text) {
  auto value = parse_param_text(spec, text);
  if (const auto* fault = std::get_if<std::string>(&value))
    throw InputError(spec.option(), *fault);
  return std::get<ParamValue>(std::move(value));
}

std::variant<ParamValue, std::string> parse_param_text(const ParamSpec& s, std::string_view text) {
  ParamValue value = std::string(text);
  if (s.kind == ParamKind::real || s.kind == ParamKind::integer) {
    // strtod reads nan and inf too, so that they are refused as values, not as text.
    const std::string copy(text);
    char* end = nullptr;
    const double v = std::strtod(copy.c_str(), &end);
    if (copy.empty() || std::isspace(static_cast<unsigned char>(copy[0])) != 0 ||
        end != copy.c_str() + copy.size())
      return fault(s, "'" + copy + "'");
    value = v;
  } else if (s.kind == ParamKind::boolean) {
    if (text == "true" || text == "on" || text == "1")
      value = true;
    else if (text == "false" || text == "off" || text == "0")
      value = false;
  }
  if (auto f = param_fault(s, value))
    return *f;
  return normalise_param(s, value);
}

ParamValue normalise_param(const ParamSpec& s, const ParamValue& value) {
  if (s.kind == ParamKind::integer) {
    if (const auto* d = std::get_if<double>(&value))
      return static_cast<std::int64_t>(*d);
  }
  if (s.kind == ParamKind::real) {
    if (const auto* i = std::get_if<std::int64_t>(&value))
      return static_cast<double>(*i);
  }
  return value;
}

}  // namespace tandem
