// SPDX-License-Identifier: MIT
// Internal to litkit: the scalar type that turns litkit/equations.hpp into
// GLSL. An Expr does not compute; each operation adds a node to an expression
// DAG (a value the template names once and uses twice is one node with two
// parents). Printing the DAG gives GLSL statements: a node used more than
// once becomes a temporary, everything else is inlined with the fewest
// parentheses that keep the templates' order of evaluation. Nothing is
// simplified, so the GPU performs the same float operations as the CPU.
//
// The operations are the ones equations.hpp asks of a T: + - * /, unary -,
// comparisons giving a Mask, and select, max, min, pow, sqrt, floor found by
// argument-dependent lookup (hence namespace litkit::glsl).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/equations.hpp"
#include "litkit/lighting.hpp"

namespace litkit::glsl {

struct Node;
using NodePtr = std::shared_ptr<const Node>;

// One operation of the DAG. Literal and Variable are leaves; the others use
// args[0..arity).
struct Node {
    enum class Op {
        Literal,   // value
        Variable,  // name, a GLSL lvalue such as "p.x" or "material.ka"
        Add,
        Subtract,
        Multiply,
        Divide,
        Negate,
        Less,  // comparisons: masks (GLSL bool)
        LessEqual,
        Greater,
        GreaterEqual,
        Select,  // args[0] ? args[1] : args[2]
        Max,
        Min,
        Pow,
        Sqrt,
        Floor,
    };
    Op op = Op::Literal;
    float value = 0.0f;
    std::string name;
    std::array<NodePtr, 3> args{};
};

// A float-valued expression.
class Expr {
  public:
    // A float literal; T(1), T(0.5f) in the templates.
    explicit Expr(float value);
    Expr() : Expr(0.0f) {}  // 0, so that aggregates of Expr can be declared
    explicit Expr(NodePtr node) : node_(std::move(node)) {}
    // A named GLSL input, e.g. Expr::variable("p.x").
    static Expr variable(std::string name);

    const NodePtr& node() const { return node_; }

  private:
    NodePtr node_;
};

// A bool-valued expression: the result of a comparison.
class Mask {
  public:
    explicit Mask(NodePtr node) : node_(std::move(node)) {}
    const NodePtr& node() const { return node_; }

  private:
    NodePtr node_;
};

Expr operator+(const Expr& a, const Expr& b);
Expr operator-(const Expr& a, const Expr& b);
Expr operator*(const Expr& a, const Expr& b);
Expr operator/(const Expr& a, const Expr& b);
Expr operator-(const Expr& a);
Mask operator<(const Expr& a, const Expr& b);
Mask operator<=(const Expr& a, const Expr& b);
Mask operator>(const Expr& a, const Expr& b);
Mask operator>=(const Expr& a, const Expr& b);
Expr select(const Mask& mask, const Expr& if_true, const Expr& if_false);
Expr max(const Expr& a, const Expr& b);
Expr min(const Expr& a, const Expr& b);
Expr pow(const Expr& base, const Expr& exponent);
Expr sqrt(const Expr& a);
Expr floor(const Expr& a);

// {name.x, name.y, name.z}: a GLSL vec3 input.
equations::Vec3<Expr> vec3_variable(const std::string& name);
// The fields of a GLSL Material input called `name`.
equations::MaterialT<Expr> material_variable(const std::string& name);

// ---- Printing ----

// `value` as a GLSL float literal that reads back as exactly `value`:
// 1 → "1.0", 0.5 → "0.5", 1e-6 → "1e-06". Throws std::invalid_argument for
// infinities and NaN, which GLSL cannot spell.
std::string float_literal(float value);

struct PrintOptions {
    // The function that Pow nodes call.
    std::string pow_function = "pow";
};

// `value` as one GLSL expression, everything inlined (no temporaries).
std::string to_glsl(const Expr& value, const PrintOptions& options = {});
std::string to_glsl(const Mask& value, const PrintOptions& options = {});

// One result of a generated function: `target = value;`, or `return value;`
// when target is empty.
struct Output {
    std::string target;
    Expr value;
};

// A named temporary for every node that is structurally equal to `pattern`
// (same operations on the same variables and literals), even one used once:
// names for what the templates name (n_dot_l, light_distance).
struct Hint {
    std::string name;
    Expr pattern;
};

// GLSL statements computing `outputs`, one per line, each line prefixed with
// `indent`: first the temporaries (`float t0 = ...;`, `bool t1 = ...;`) in
// dependency order, one for every operation used more than once or matching
// a hint, named after the first matching hint or else t0, t1, ...; then the
// outputs in order.
std::string print_statements(std::span<const Output> outputs, std::span<const Hint> hints = {},
                             const PrintOptions& options = {}, std::string_view indent = "    ");

// The same statements in their two parts, for a function body that declares
// its result between them (glsl.cpp).
struct Statements {
    std::string temporaries;  // `float t0 = ...;` lines
    std::string assignments;  // `target = ...;` or `return ...;` lines
};
Statements statements(std::span<const Output> outputs, std::span<const Hint> hints,
                      const PrintOptions& options, std::string_view indent);

// ---- Evaluation (tests and debugging) ----

// Values of the variables, by name ("p.x").
using Bindings = std::map<std::string, float, std::less<>>;

// The value of the expression in float arithmetic, each operation as the
// float instantiation of equations.hpp performs it. Throws std::out_of_range
// for a variable missing from `bindings`.
float evaluate(const Expr& value, const Bindings& bindings);
bool evaluate(const Mask& value, const Bindings& bindings);

// ---- The generated GLSL functions ----

// One GLSL function: its signature, a doc comment, and its results as
// expressions over its parameters.
struct Function {
    std::string doc;          // comment text, lines separated by '\n', without "// "
    std::string return_type;  // "float", "vec3" or a struct name
    std::string name;
    std::string parameters;  // "vec3 travel_unit"
    // float: one output with an empty target (`return ...;`); otherwise
    // targets such as "result.to_light.x" of a local `return_type result;`.
    std::vector<Output> outputs;
    std::vector<Hint> hints;
};

// equations::directional_incidence, point_incidence, spot_factor,
// reflection_terms<reflection>, ambient_term, direct_term and normalize
// (GLSL name unit_vector) over GLSL parameters.
Function directional_incidence_function();
Function point_incidence_function();
Function spot_factor_function();
Function reflection_terms_function(Reflection reflection);
Function ambient_term_function();
Function direct_term_function();
Function unit_vector_function();

// The function's GLSL text: doc comment, signature and body.
std::string print_function(const Function& function, const PrintOptions& options = {});

// The PrintOptions of the shaders: Pow calls `power`, a GLSL helper that is
// pow with 0^0 = 1 (defined in every shader next to the generated functions).
PrintOptions shader_print_options();

}  // namespace litkit::glsl
