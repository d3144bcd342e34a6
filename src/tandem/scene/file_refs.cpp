#include "tandem/scene/file_refs.hpp"

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"

namespace tandem {
namespace {

bool is_under(const std::filesystem::path& p, const std::filesystem::path& root) {
  auto r = root.begin();
  auto q = p.begin();
  for (; r != root.end(); ++r, ++q) {
    if (r->empty())
      continue;  // a trailing separator
    if (q == p.end() || *q != *r)
      return false;
  }
  return true;
}

}  // namespace

std::filesystem::path resolve_reference(const std::string& reference,
                                        const std::filesystem::path& referrer,
                                        const FileAccess& access) {
  const std::string source = referrer.string();
  if (reference.empty())
    throw InputError(source, "empty file name");
  check_file_name(reference, source);
  std::string name = reference;
  const auto scheme = name.find("://");
  if (scheme != std::string::npos) {
    const std::string kind = name.substr(0, scheme);
    if (kind != "file") {
      throw InputError(source, "cannot resolve '" + reference + "': " + kind +
                                   ":// URIs are not supported; give a path relative to " +
                                   referrer.filename().string());
    }
    name = name.substr(scheme + 3);
  }
  std::filesystem::path p(name);
  if (p.is_relative())
    p = referrer.parent_path() / p;
  std::error_code ec;
  std::filesystem::path resolved = std::filesystem::weakly_canonical(p, ec);
  if (ec)
    resolved = p.lexically_normal();
  if (access.roots.empty())
    return resolved;
  for (const auto& root : access.roots) {
    std::filesystem::path r = std::filesystem::weakly_canonical(root, ec);
    if (ec)
      r = root.lexically_normal();
    if (is_under(resolved, r))
      return resolved;
  }
  throw InputError(source, "'" + reference + "' resolves to " + resolved.string() +
                               ", outside the folders tandem may read (" +
                               access.roots.front().string() +
                               (access.roots.size() > 1 ? ", ..." : "") +
                               "); allow its folder with --allow-dir");
}

}  // namespace tandem
