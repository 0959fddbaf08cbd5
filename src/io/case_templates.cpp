#include "case_templates.hpp"

#include <algorithm>
#include <set>
#include <string_view>

namespace hbtrack {

namespace {

constexpr std::string_view kNodeMark = "{node}";

bool has_mark(const toml::value& v) { return v.is_string() && v.as_string().str.find(kNodeMark) != std::string::npos; }

// The dof names of a block: one string or an array (read_elements checks their types).
std::vector<const toml::value*> dof_values(const toml::value& dofs) {
  std::vector<const toml::value*> out;
  if (dofs.is_array())
    for (const toml::value& d : dofs.as_array()) out.push_back(&d);
  else
    out.push_back(&dofs);
  return out;
}

std::string dof_field(const std::string& field, const toml::value& dofs, std::size_t i) {
  return field + ".dofs" + (dofs.is_array() ? "[" + std::to_string(i) + "]" : "");
}

bool is_per_node(const toml::value& v) { return v.is_table() && v.contains("per_node"); }

void replace_marks(toml::value& v, const std::string& node) {
  if (!v.is_string()) return;
  std::string& s = v.as_string().str;
  for (std::size_t at = s.find(kNodeMark); at != std::string::npos; at = s.find(kNodeMark, at + node.size()))
    s.replace(at, kNodeMark.size(), node);
}

// A block without `nodes`: neither `{node}` nor per_node means anything there.
void check_plain_block(const CaseReader& in, const toml::value& block, const std::string& field) {
  if (const toml::value* dofs = in.find(block, "dofs")) {
    const std::vector<const toml::value*> values = dof_values(*dofs);
    for (std::size_t i = 0; i < values.size(); ++i)
      if (has_mark(*values[i]))
        in.fail(values[i], dof_field(field, *dofs, i), "{node} is replaced only in a template: add nodes = [\"n1\", ...] to the block");
  }
  for (const auto& [key, value] : block.as_table())
    if (is_per_node(value))
      in.fail(&value, field + "." + key + ".per_node", "needs nodes = [\"n1\", ...] in the block (one entry per node)");
}

// The nodes of a template: a non-empty array of distinct, non-empty strings.
std::vector<std::string> read_nodes(const CaseReader& in, const toml::value& nodes, const std::string& field) {
  if (!nodes.is_array()) in.fail(&nodes, field, "expected an array of node names, e.g. [\"n1\", \"n2\"]");
  if (nodes.as_array().empty()) in.fail(&nodes, field, "an empty list (give at least one node, or drop nodes for a single element)");
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < nodes.as_array().size(); ++i) {
    const toml::value& node = nodes.as_array()[i];
    const std::string name = in.string(node, field + "[" + std::to_string(i) + "]");
    if (name.empty()) in.fail(&node, field + "[" + std::to_string(i) + "]", "an empty node name");
    if (!seen.insert(name).second) in.fail(&node, field + "[" + std::to_string(i) + "]", "node '" + name + "' appears twice");
    out.push_back(name);
  }
  return out;
}

}  // namespace

void expand_element_templates(const CaseReader& in, toml::value& root) {
  toml::value* elements = root.is_table() && root.contains("elements") ? &root.at("elements") : nullptr;
  if (!elements || !elements->is_array()) return;  // read_elements reports a wrong type
  toml::array expanded;
  std::size_t from_templates = 0;
  for (const toml::value& block : elements->as_array()) {
    const std::string field = "elements[" + std::to_string(expanded.size()) + "]";
    const toml::value* nodes_value = block.is_table() ? in.find(block, "nodes") : nullptr;
    if (!nodes_value) {
      if (block.is_table()) check_plain_block(in, block, field);
      expanded.push_back(block);
      continue;
    }
    const std::vector<std::string> nodes = read_nodes(in, *nodes_value, field + ".nodes");
    const toml::value& dofs = in.require(block, "dofs", field + ".dofs");
    if (!dofs.is_array() && !dofs.is_string()) in.fail(&dofs, field + ".dofs", "expected an array of dof names");
    const std::vector<const toml::value*> names = dof_values(dofs);
    if (std::none_of(names.begin(), names.end(), [](const toml::value* d) { return has_mark(*d); }))
      in.fail(nodes_value, field + ".nodes", "no name in dofs contains {node} (every element would act on the same dofs)");
    std::vector<std::string> per_node;
    for (const auto& [key, value] : block.as_table()) {
      if (!is_per_node(value)) continue;
      const std::string per_field = field + "." + key + ".per_node";
      if (key == "dofs" || key == "nodes") in.fail(&value, per_field, "not allowed here (dof names vary with {node})");
      if (value.as_table().size() != 1) in.fail(&value, field + "." + key, "a per_node table takes no other key");
      const toml::value& list = value.at("per_node");
      if (!list.is_array() || list.as_array().size() != nodes.size())
        in.fail(&list, per_field, "expected an array with one entry per node (" + std::to_string(nodes.size()) + ")");
      per_node.push_back(key);
    }
    from_templates += nodes.size();
    if (from_templates > kMaxTemplateElements)
      in.fail(nodes_value, field + ".nodes", "templates give more than " + std::to_string(kMaxTemplateElements) + " elements");
    // The block without its node and per_node lists, copied per node: copying the whole block
    // copied every list once per node (20 000 nodes and 5 lists: minutes). A copy keeps the
    // lines of its values for the errors of read_elements.
    toml::value skeleton = block;
    skeleton.as_table().erase("nodes");
    for (const std::string& key : per_node) skeleton.as_table().at(key) = toml::value();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      toml::value element = skeleton;
      toml::table& table = element.as_table();
      toml::value& element_dofs = table.at("dofs");
      if (element_dofs.is_array())
        for (toml::value& d : element_dofs.as_array()) replace_marks(d, nodes[i]);
      else
        replace_marks(element_dofs, nodes[i]);
      for (const std::string& key : per_node) table.at(key) = block.at(key).at("per_node").as_array()[i];
      expanded.push_back(std::move(element));
    }
  }
  elements->as_array() = std::move(expanded);
}

}  // namespace hbtrack
