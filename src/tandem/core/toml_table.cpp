#include "tandem/core/toml_table.hpp"

#include <cmath>

#include "tandem/core/error.hpp"

namespace tandem {

toml::table parse_toml(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(source + ":" + std::to_string(e.source().begin.line),
                     "invalid TOML: " + std::string(e.description()));
  }
}

TomlTable::TomlTable(const toml::table& table, std::string source, std::string where)
    : table_(&table), source_(std::move(source)), where_(std::move(where)), prefix_(where_ + ".") {}

TomlTable::TomlTable(const toml::table& table, std::string source, std::string where,
                     std::string prefix)
    : table_(&table),
      source_(std::move(source)),
      where_(std::move(where)),
      prefix_(std::move(prefix)) {}

std::string TomlTable::name(std::string_view key) const {
  return prefix_ + std::string(key);
}

std::string TomlTable::at(const toml::node& node) const {
  return source_ + ":" + std::to_string(node.source().begin.line);
}

std::string TomlTable::at_table() const {
  return table_->source().begin.line > 0 ? at(*table_) : source_;
}

bool TomlTable::has(std::string_view key) const {
  return table_->contains(key);
}

const toml::node* TomlTable::get(std::string_view key) {
  read_.insert(std::string(key));
  return table_->get(key);
}

const toml::node& TomlTable::require(std::string_view key) {
  const toml::node* n = get(key);
  if (!n)
    throw InputError(at_table(), where_ + " needs '" + std::string(key) + "'");
  return *n;
}

void TomlTable::each(
    const std::function<void(const std::string& key, const toml::node& node)>& visit) {
  for (auto&& [key, node] : *table_) {
    read_.insert(std::string(key.str()));
    visit(std::string(key.str()), node);
  }
}

std::vector<std::string> TomlTable::unread() const {
  std::vector<std::string> keys;
  for (auto&& [key, node] : *table_) {
    if (!read_.contains(key.str()))
      keys.emplace_back(key.str());
  }
  return keys;
}

void TomlTable::reject_unknown() const {
  for (auto&& [key, node] : *table_) {
    if (!read_.contains(key.str()))
      throw InputError(at(node), "unknown key '" + std::string(key.str()) + "' in " + where_);
  }
}

void TomlTable::fail(const toml::node& node, std::string_view key, const std::string& fault) const {
  throw InputError(at(node), name(key) + " " + fault);
}

double TomlTable::number(const toml::node& node, std::string_view key) const {
  auto v = node.value<double>();
  if (!v || !(node.is_floating_point() || node.is_integer()))
    fail(node, key, "must be a number");
  if (!std::isfinite(*v))
    fail(node, key, "must be finite");
  return *v;
}

double TomlTable::number(std::string_view key) {
  return number(require(key), key);
}

std::optional<double> TomlTable::optional_number(std::string_view key) {
  const toml::node* n = get(key);
  if (!n)
    return std::nullopt;
  return number(*n, key);
}

double TomlTable::positive(std::string_view key) {
  const toml::node& n = require(key);
  const double v = number(n, key);
  if (!(v > 0.0))
    fail(n, key, "must be positive");
  return v;
}

std::int64_t TomlTable::integer(const toml::node& node, std::string_view key,
                                std::int64_t min) const {
  // Only an integer node: value<std::int64_t>() would convert a float, undefined out of range
  // (found by the experiment fuzz target: seeds = 2e32).
  const auto* v = node.as_integer();
  if (v == nullptr || v->get() < min) {
    fail(node, key,
         min == 0   ? "must be a non-negative integer"
         : min == 1 ? "must be a positive integer"
                    : "must be an integer of at least " + std::to_string(min));
  }
  return v->get();
}

std::int64_t TomlTable::integer(std::string_view key, std::int64_t min) {
  return integer(require(key), key, min);
}

std::optional<std::int64_t> TomlTable::optional_integer(std::string_view key, std::int64_t min) {
  const toml::node* n = get(key);
  if (!n)
    return std::nullopt;
  return integer(*n, key, min);
}

std::uint64_t TomlTable::positive_integer(std::string_view key) {
  return static_cast<std::uint64_t>(integer(key, 1));
}

std::string TomlTable::string(const toml::node& node, std::string_view key) const {
  auto v = node.value<std::string>();
  if (!v || !node.is_string())
    fail(node, key, "must be a string");
  return *v;
}

std::string TomlTable::string(std::string_view key) {
  return string(require(key), key);
}

std::optional<std::string> TomlTable::optional_string(std::string_view key) {
  if (!has(key))
    return std::nullopt;
  return string(key);
}

std::vector<double> TomlTable::numbers(const toml::node& node, std::string_view key,
                                       std::size_t min_count, std::size_t max_count) const {
  const toml::array* a = node.as_array();
  if (!a)
    fail(node, key, "must be an array of numbers");
  if (a->size() < min_count || a->size() > max_count) {
    fail(node, key,
         min_count == max_count ? "must have " + std::to_string(min_count) + " numbers"
                                : "must have " + std::to_string(min_count) + " to " +
                                      std::to_string(max_count) + " numbers");
  }
  std::vector<double> out;
  for (const auto& e : *a)
    out.push_back(number(e, key));
  return out;
}

std::vector<double> TomlTable::numbers(std::string_view key, std::size_t min_count,
                                       std::size_t max_count) {
  return numbers(require(key), key, min_count, max_count);
}

TomlTable TomlTable::subtable(std::string_view key) {
  const toml::node& n = require(key);
  const toml::table* t = n.as_table();
  if (!t)
    fail(n, key, "must be a table");
  return TomlTable(*t, source_, name(key));
}

const toml::array& TomlTable::table_array(std::string_view key, bool non_empty,
                                          std::string_view hint) {
  const toml::node& n = require(key);
  const toml::array* a = n.as_array();
  if (!a || (non_empty && a->empty())) {
    fail(n, key,
         std::string(non_empty ? "must be a non-empty array of tables"
                               : "must be an array of tables") +
             std::string(hint));
  }
  return *a;
}

TomlTable TomlTable::array_item(const toml::node& element, std::string_view key,
                                std::string item_where, std::string_view hint) const {
  const toml::table* t = element.as_table();
  if (!t)
    fail(element, key, "must contain tables" + std::string(hint));
  return TomlTable(*t, source_, std::move(item_where));
}

ParamValue toml_param(const toml::node& n) {
  if (auto i = n.value_exact<std::int64_t>())
    return *i;
  if (n.is_floating_point())
    return *n.value<double>();
  if (auto b = n.value_exact<bool>())
    return *b;
  if (auto t = n.value_exact<std::string>())
    return *t;
  return std::string(n.is_array() ? "<an array>" : n.is_table() ? "<a table>" : "<a value>");
}

}  // namespace tandem
