#pragma once
// [model] dofs: the names of the model's dofs, as a list, as a count N (x1 .. xN) or read from a
// file ({ file = "names.txt" }: one name per line; or the summary.json of `hbtrack reduce`).
#include <string>
#include <vector>

#include "case_reader.hpp"

namespace hbtrack {

// The most dofs a case's model may have (`dofs = N`, a names list or file, `chain.count`). Its M,
// C and K are dense, and the condensation keeps a dense complex LU factor of the linear dofs'
// dynamic stiffness per harmonic, (H + 1) 16 n^2 bytes: at 4000 dofs and H = 10, 2.8 GB besides
// the three 128 MB matrices; 10 000 dofs would take 17.6 GB, more than a workstation has. A
// larger model is reduced first (`hbtrack reduce`, which reads its matrices sparse).
inline constexpr int kMaxModelDofs = 4000;

// A names file (or a summary.json) larger than this is refused: at 16 MiB it already names a
// model whose dense matrices would not fit in memory.
inline constexpr std::size_t kMaxDofNamesFileBytes = std::size_t{16} << 20;

// Why `name` cannot head a CSV column ("" when it can): empty, or holding a comma, a double quote
// or a control character (tab, newline, NUL). `what` names it in the message ("dof name").
std::string column_name_problem(const std::string& what, const std::string& name);

// "x1" .. "xN": the names of `dofs = N` and of the chain model.
std::vector<std::string> numbered_dof_names(int n);

// The names a `dofs` list or `{ file = ... }` table gives, checked non-empty and unique; `field`
// is "model.dofs". An integer `dofs` is the caller's (its names follow the matrices' size).
std::vector<std::string> read_dof_names(const CaseReader& in, const toml::value& dofs, const std::string& field);

}  // namespace hbtrack
