#pragma once
// Reading tandem's TOML files (scenarios, experiments) one table at a time.
//
// TomlTable wraps a table of a parsed document. It remembers which keys were read, so that a
// misspelt key is reported (reject_unknown) instead of silently ignored, and its typed getters
// throw InputError naming the file and line of the fault ("scene.toml:12: scenario.space.min must
// have 3 numbers").
//
// Names in messages: a table has a name, `where` ("scenario.space", "the experiment"), used for
// the table as a whole ("scenario.space needs 'min'", "unknown key 'x' in scenario.space"); a value
// is named by a prefix and its key ("scenario.space." + "min"). The prefix is `where` + "." unless
// given: a file's top level usually names its values by their bare keys ("seeds must be a positive
// integer") and itself in words ("the experiment needs 'name'").
//
// A TomlTable refers to the parsed document, which must outlive it. Not thread-safe (it records
// reads); use one per thread.

#include <toml++/toml.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "tandem/core/parameter.hpp"

namespace tandem {

/// Parses TOML text; `source` names it in messages. Throws InputError "source:line: invalid TOML:
/// ..." for malformed text.
toml::table parse_toml(std::string_view text, const std::string& source);

/// A TOML value as a parameter value, in its TOML type (integer, float, boolean, string); an array
/// or a table becomes a text that no numeric, boolean or choice declaration accepts. The declared
/// kind and range are checked by whoever sets the tunable (runs/run_spec.hpp, set_tunable).
ParamValue toml_param(const toml::node& n);

class TomlTable {
 public:
  /// Values are named `where` + "." + key.
  TomlTable(const toml::table& table, std::string source, std::string where);
  /// Values are named `prefix` + key ("" for bare keys).
  TomlTable(const toml::table& table, std::string source, std::string where, std::string prefix);

  const std::string& where() const { return where_; }
  const std::string& source() const { return source_; }
  /// How messages name the value of `key` ("scenario.space.min").
  std::string name(std::string_view key) const;
  /// "file:line" of a node of the document.
  std::string at(const toml::node& node) const;
  /// "file:line" of this table ("file" for a document's root, which has no line).
  std::string at_table() const;

  /// Whether the key is there; does not count as reading it.
  bool has(std::string_view key) const;
  /// The key's node, or nullptr; counts as reading it.
  const toml::node* get(std::string_view key);
  /// The key's node; throws "<where> needs '<key>'" when it is missing.
  const toml::node& require(std::string_view key);
  /// Calls `visit` with every key and its node, in the file's order; all count as read.
  void each(const std::function<void(const std::string& key, const toml::node& node)>& visit);
  /// The keys not read so far, in the file's order.
  std::vector<std::string> unread() const;
  /// Throws "unknown key '<key>' in <where>" at the first key not read.
  void reject_unknown() const;

  /// Throws InputError at the node: "<name(key)> <fault>".
  [[noreturn]] void fail(const toml::node& node, std::string_view key,
                         const std::string& fault) const;

  /// A finite number (integer or floating point).
  double number(const toml::node& node, std::string_view key) const;
  double number(std::string_view key);
  std::optional<double> optional_number(std::string_view key);
  /// A number above zero.
  double positive(std::string_view key);

  /// An integer of at least `min` (faults: "must be a non-negative integer" for min 0, "must be a
  /// positive integer" for min 1, "must be an integer of at least <min>" otherwise).
  std::int64_t integer(const toml::node& node, std::string_view key, std::int64_t min) const;
  std::int64_t integer(std::string_view key, std::int64_t min);
  std::optional<std::int64_t> optional_integer(std::string_view key, std::int64_t min);
  std::uint64_t positive_integer(std::string_view key);

  std::string string(const toml::node& node, std::string_view key) const;
  std::string string(std::string_view key);
  std::optional<std::string> optional_string(std::string_view key);

  /// An array of `min_count` to `max_count` numbers.
  std::vector<double> numbers(const toml::node& node, std::string_view key, std::size_t min_count,
                              std::size_t max_count) const;
  std::vector<double> numbers(std::string_view key, std::size_t min_count, std::size_t max_count);

  /// The table at `key`, named name(key).
  TomlTable subtable(std::string_view key);
  /// The array at `key`; faults "must be a [non-empty ]array of tables<hint>".
  const toml::array& table_array(std::string_view key, bool non_empty, std::string_view hint = "");
  /// An element of such an array as a table named `item_where`; fault "must contain
  /// tables<hint>", charged to `key`.
  TomlTable array_item(const toml::node& element, std::string_view key, std::string item_where,
                       std::string_view hint = "") const;

 private:
  const toml::table* table_;
  std::string source_;
  std::string where_;
  std::string prefix_;
  std::set<std::string, std::less<>> read_;
};

}  // namespace tandem
