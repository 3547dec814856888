#pragma once
// Renders the registered types' own declarations (ParamSpec) as reference documentation, so the
// docs can never disagree with what scene validation accepts.
#include <string>
#include <vector>

#include "frictionlab/plugins/registry.hpp"

namespace frictionlab::cli {

enum class DocFormat { text, markdown, json };

std::string render_doc(const std::vector<const TypeInfo*>& types, DocFormat format);

}  // namespace frictionlab::cli
