#pragma once
// Node tables of the model-reduction verbs (format in docs/reduction.md):
//   nodes.csv:            `node,x,y,z`, one row per node
//   boundary node lists:  node ids separated by commas, blanks or newlines; `#` starts a comment
//   boundary_nodes.csv:   each boundary node's position, radius and local frame
// Bad input throws hbtrack::CaseError "<path>:<line>: <rule>".
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "hbtrack/model/cylindrical_frame.hpp"

namespace hbtrack::cli {

struct NodeRecord {
  int id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

// A first line that does not start with a number is taken as the header.
std::vector<NodeRecord> read_node_table(const std::string& path);
void write_node_table(const std::string& path, const std::vector<NodeRecord>& nodes);

std::vector<int> read_node_list(const std::string& path);
void write_node_list(const std::string& path, const std::vector<int>& ids, const std::string& comment);

// Header: node,x,y,z,radius,radial_x,radial_y,radial_z,circumferential_x,...,axial_z.
void write_boundary_nodes(const std::string& path, const std::vector<NodeRecord>& nodes, const std::vector<CylindricalFrame>& frames);

}  // namespace hbtrack::cli
