#include "lac/integrators/method_info.hpp"

#include "lac/common/error.hpp"

namespace lac {

std::string method_names_text(std::span<const MethodInfo> methods, std::string_view separator) {
  std::string text;
  for (const MethodInfo& m : methods) {
    if (!text.empty()) text.append(separator);
    text.append(m.name);
    for (std::string_view alias : m.aliases) text.append(" (alias ").append(alias).append(")");
  }
  return text;
}

const MethodInfo* find_method(std::span<const MethodInfo> methods, std::string_view name) {
  for (const MethodInfo& m : methods) {
    if (m.name == name) return &m;
    for (std::string_view alias : m.aliases)
      if (alias == name) return &m;
  }
  return nullptr;
}

bool takes_option(const MethodInfo& method, std::string_view option) {
  for (const MethodOption& o : method.options)
    if (o.name == option) return true;
  return false;
}

void require_option(const MethodInfo& method, std::string_view option) {
  if (takes_option(method, option)) return;
  std::string takes;
  for (const MethodOption& o : method.options) takes.append(takes.empty() ? "--" : ", --").append(o.name);
  throw_input_error(method.name, option,
                    "not applicable to " + std::string(method.name) + "; " + std::string(method.name) + " takes " +
                        (takes.empty() ? std::string("no options") : takes));
}

}  // namespace lac
