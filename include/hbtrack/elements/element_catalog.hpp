#pragma once
// The element types a case file may name: for each, how it is built and the properties it reads
// (name, unit, range, default, one-line doc). The case reader (io/case_elements.cpp), the Python
// module (hbtrack.element_types and the helpers of hbtrack.elements) and docs/case-file.md (checked
// by tests/test_element_catalog_docs.cpp) all take them from here, so adding an element is its
// class and one entry in element_catalog.cpp.
#include <Eigen/Dense>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

// The values a property admits, at the case's nominal parameter values.
enum class PropertyRange { any, positive, nonnegative, nonzero, above_minus_one, at_least_one };
std::string to_string(PropertyRange range);  // "", "> 0", ">= 0", "!= 0", "> -1", ">= 1"
bool admits(PropertyRange range, double value);

// A scalar property: a number or a parameter binding in the case file, a column of
// dforce_dproperty, a parameter tracking can vary.
struct PropertySpec {
  std::string name;
  std::string unit;  // in the model's units: F force, L length, s time; "1" for none
  PropertyRange range = PropertyRange::any;
  std::optional<double> fallback;  // the value when the case omits it; none: required
  std::string doc;                 // what it is, in one line (docstrings, element_types())
  std::string why{};               // why the range, for the message ("" when it goes without saying)
};

// A key of [[elements]] that decides how the element is built (not a property: not bindable).
struct ElementKey {
  enum class Kind {
    choice,         // a string among `values`
    integer,        // an integer in [min, max]
    integer_rows,   // rows of integers in [min, max], one row per `row`, one `entry` per dof
    property_rows,  // rows of properties, one per row of the integer_rows key, one `entry` per dof
  };
  std::string name;
  Kind kind = Kind::choice;
  std::vector<std::string> values{};  // choice: what it takes, the default first
  std::string fallback{};             // the value when the case omits it, as the case file writes it; "": required
  int min = 0, max = 0;               // integer, integer_rows
  std::string row{}, entry{};         // integer_rows, property_rows: what a row and an entry are, for messages
  std::string doc{};                  // what it decides, in one line
};

// The keys' values for one element of a case: choices (the default where absent), integers and
// integer rows as read.
struct ElementSetup {
  std::map<std::string, std::string> choices;
  std::map<std::string, int> integers;
  std::map<std::string, Eigen::MatrixXi> integer_rows;
};

// A key's value the element cannot be built with: the reader names the key.
class ElementKeyError : public std::invalid_argument {
 public:
  ElementKeyError(std::string key, const std::string& rule) : std::invalid_argument(rule), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// The element and its properties in the order of `properties` (property_names()).
struct ElementBuild {
  std::shared_ptr<NonlinearElement> element;
  std::vector<PropertySpec> properties;
};

struct ElementType {
  std::string type;
  std::string summary;  // the force law in one line
  // How the element sees its dofs: weighted ones act along `directions` combinations of any
  // number of dofs, `weights`: one direction (ScalarElements), d = w.x, by default [1] on one dof
  // and [1, -1] between two; two directions (a slider in a plane, ElasticDryFriction2D),
  // u = W x with W 2 x k rows, by default the identity on [x, y] and the relative motion
  // [[1, 0, -1, 0], [0, 1, 0, -1]] on [x_a, y_a, x_b, y_b]. The others take exactly the dofs
  // named in `dof_names` (empty: any number, each its own).
  bool weighted = true;
  std::vector<std::string> dof_names;
  std::vector<ElementKey> keys;
  ElementBuild (*build)(const ElementSetup& setup) = nullptr;  // throws ElementKeyError
  int directions = 1;                                          // of a weighted type: the rows of `weights` (see `weighted`)
};

// Every element type, in the order of the documentation.
const std::vector<ElementType>& element_catalog();
// The type named `type`; nullptr when there is none.
const ElementType* find_element_type(const std::string& type);

// Every combination of a type's choice values (integers at their defaults, integer rows a single
// row of ones): the variants whose properties the documentation and Python list.
std::vector<ElementSetup> element_variants(const ElementType& type);

}  // namespace hbtrack
