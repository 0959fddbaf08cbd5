#pragma once
// Element templates: an [[elements]] block with `nodes = ["n1", "n2", ...]` stands for one
// element per node, in the nodes' order, where every `{node}` in its dof names is replaced by
// the node and a property `KEY.per_node = [v1, v2, ...]` takes the node's entry.
#include "case_reader.hpp"

namespace hbtrack {

// A case expands to at most this many elements from templates (each is a copy of its block).
inline constexpr std::size_t kMaxTemplateElements = 20000;

// Replaces root.elements by its expanded list, in place, before `--set` overrides and the
// elements are read: elements[i] (in --set and in errors) is element i of the expanded list,
// and an error in a template names the index of its first element. Values keep their lines.
void expand_element_templates(const CaseReader& in, toml::value& root);

}  // namespace hbtrack
