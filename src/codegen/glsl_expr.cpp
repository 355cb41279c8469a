// SPDX-License-Identifier: MIT
// glsl::Expr (codegen/glsl_expr.hpp): building the expression graph, printing
// it as GLSL, and evaluating it (for tests).
#include "codegen/glsl_expr.hpp"
#include "litkit/error.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace litkit::glsl {

// ---- Expr: building the DAG ----

namespace {

using Op = Node::Op;

NodePtr make_node(Op op, const NodePtr& a = nullptr, const NodePtr& b = nullptr,
                  const NodePtr& c = nullptr) {
    auto node = std::make_shared<Node>();
    node->op = op;
    node->args = {a, b, c};
    return node;
}

int arity(Op op) {
    switch (op) {
        case Op::Literal:
        case Op::Variable:
            return 0;
        case Op::Negate:
        case Op::Sqrt:
        case Op::Floor:
            return 1;
        case Op::Select:
            return 3;
        default:
            return 2;
    }
}

bool is_leaf(Op op) { return arity(op) == 0; }

bool is_comparison(Op op) {
    return op == Op::Less || op == Op::LessEqual || op == Op::Greater || op == Op::GreaterEqual;
}

}  // namespace

Expr::Expr(float value) {
    auto node = std::make_shared<Node>();
    node->op = Op::Literal;
    node->value = value;
    node_ = std::move(node);
}

Expr Expr::variable(std::string name) {
    auto node = std::make_shared<Node>();
    node->op = Op::Variable;
    node->name = std::move(name);
    return Expr(NodePtr(std::move(node)));
}

Expr operator+(const Expr& a, const Expr& b) {
    return Expr(make_node(Op::Add, a.node(), b.node()));
}
Expr operator-(const Expr& a, const Expr& b) {
    return Expr(make_node(Op::Subtract, a.node(), b.node()));
}
Expr operator*(const Expr& a, const Expr& b) {
    return Expr(make_node(Op::Multiply, a.node(), b.node()));
}
Expr operator/(const Expr& a, const Expr& b) {
    return Expr(make_node(Op::Divide, a.node(), b.node()));
}
Expr operator-(const Expr& a) { return Expr(make_node(Op::Negate, a.node())); }
Mask operator<(const Expr& a, const Expr& b) {
    return Mask(make_node(Op::Less, a.node(), b.node()));
}
Mask operator<=(const Expr& a, const Expr& b) {
    return Mask(make_node(Op::LessEqual, a.node(), b.node()));
}
Mask operator>(const Expr& a, const Expr& b) {
    return Mask(make_node(Op::Greater, a.node(), b.node()));
}
Mask operator>=(const Expr& a, const Expr& b) {
    return Mask(make_node(Op::GreaterEqual, a.node(), b.node()));
}
Expr select(const Mask& mask, const Expr& if_true, const Expr& if_false) {
    return Expr(make_node(Op::Select, mask.node(), if_true.node(), if_false.node()));
}
Expr max(const Expr& a, const Expr& b) { return Expr(make_node(Op::Max, a.node(), b.node())); }
Expr pow(const Expr& base, const Expr& exponent) {
    return Expr(make_node(Op::Pow, base.node(), exponent.node()));
}
Expr sqrt(const Expr& a) { return Expr(make_node(Op::Sqrt, a.node())); }
Expr min(const Expr& a, const Expr& b) { return Expr(make_node(Op::Min, a.node(), b.node())); }
Expr floor(const Expr& a) { return Expr(make_node(Op::Floor, a.node())); }

equations::Vec3<Expr> vec3_variable(const std::string& name) {
    return {Expr::variable(name + ".x"), Expr::variable(name + ".y"), Expr::variable(name + ".z")};
}

equations::MaterialT<Expr> material_variable(const std::string& name) {
    equations::MaterialT<Expr> material{
        vec3_variable(name + ".color"), Expr::variable(name + ".ka"), Expr::variable(name + ".kd"),
        Expr::variable(name + ".ks"), Expr::variable(name + ".shininess")};
    for_each_model_parameter(
        [&](const ModelParameter& parameter, Expr& field) {
            field = Expr::variable(name + "." + std::string(parameter.key));
        },
        material);
    return material;
}

// ---- Printing ----

std::string float_literal(float value) {
    if (!std::isfinite(value)) {
        throw litkit::ArgumentError("GLSL has no literal for " + std::to_string(value));
    }
    // The shortest text that reads back as `value`.
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (error != std::errc{}) throw std::logic_error("float_literal: to_chars failed");
    std::string text(buffer, end);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

namespace {

// C/GLSL precedence, higher binds tighter.
constexpr int atomic = 100;  // literal, variable, call, parenthesised
constexpr int unary = 90;
constexpr int multiplicative = 80;
constexpr int additive = 70;
constexpr int relational = 60;

struct Printed {
    std::string text;
    int precedence;
};

std::string parenthesised(const Printed& printed, bool needed) {
    return needed ? "(" + printed.text + ")" : printed.text;
}

// Printer writes std::string("…") + a temporary, not a bare literal: GCC 12
// warns falsely (-Wrestrict, GCC bug 105329) on a literal + a temporary
// std::string.
class Printer {
  public:
    Printer(const PrintOptions& options, const std::unordered_map<const Node*, std::string>& names)
        : options_(options), names_(names) {}

    Printed print(const Node& node) const {
        if (auto named = names_.find(&node); named != names_.end()) return {named->second, atomic};
        const auto arg = [&](int i) { return print(*node.args[static_cast<std::size_t>(i)]); };
        switch (node.op) {
            case Op::Literal:
                return {float_literal(node.value), std::signbit(node.value) ? unary : atomic};
            case Op::Variable:
                return {node.name, atomic};
            case Op::Add:
                return binary(node, " + ", additive);
            case Op::Subtract:
                return binary(node, " - ", additive);
            case Op::Multiply:
                return binary(node, " * ", multiplicative);
            case Op::Divide:
                return binary(node, " / ", multiplicative);
            case Op::Less:
                return binary(node, " < ", relational);
            case Op::LessEqual:
                return binary(node, " <= ", relational);
            case Op::Greater:
                return binary(node, " > ", relational);
            case Op::GreaterEqual:
                return binary(node, " >= ", relational);
            case Op::Negate: {
                // "-(-x)", never "--x".
                const Printed operand = arg(0);
                return {std::string("-") + parenthesised(operand, operand.precedence <= unary),
                        unary};
            }
            case Op::Select:
                return {std::string("(") + arg(0).text + " ? " + arg(1).text + " : " + arg(2).text +
                            ")",
                        atomic};
            case Op::Max:
                return {std::string("max(") + arg(0).text + ", " + arg(1).text + ")", atomic};
            case Op::Pow:
                return {options_.pow_function + "(" + arg(0).text + ", " + arg(1).text + ")",
                        atomic};
            case Op::Sqrt:
                return {std::string("sqrt(") + arg(0).text + ")", atomic};
            case Op::Min:
                return {std::string("min(") + arg(0).text + ", " + arg(1).text + ")", atomic};
            case Op::Floor:
                return {std::string("floor(") + arg(0).text + ")", atomic};
        }
        throw std::logic_error("glsl::Printer: unknown operation");
    }

  private:
    // Left-associative: a right operand of the same precedence keeps its
    // parentheses, so a - (b - c) and a * (b * c) print as written.
    Printed binary(const Node& node, std::string_view op, int precedence) const {
        const Printed left = print(*node.args[0]);
        const Printed right = print(*node.args[1]);
        return {parenthesised(left, left.precedence < precedence) + std::string(op) +
                    parenthesised(right, right.precedence <= precedence),
                precedence};
    }

    const PrintOptions& options_;
    const std::unordered_map<const Node*, std::string>& names_;
};

bool same_structure(const Node& a, const Node& b) {
    if (&a == &b) return true;
    if (a.op != b.op) return false;
    switch (a.op) {
        case Op::Literal:
            return std::memcmp(&a.value, &b.value, sizeof a.value) == 0;
        case Op::Variable:
            return a.name == b.name;
        default:
            for (int i = 0; i < arity(a.op); ++i) {
                const auto k = static_cast<std::size_t>(i);
                if (!same_structure(*a.args[k], *b.args[k])) return false;
            }
            return true;
    }
}

}  // namespace

std::string to_glsl(const Expr& value, const PrintOptions& options) {
    const std::unordered_map<const Node*, std::string> no_names;
    return Printer(options, no_names).print(*value.node()).text;
}

std::string to_glsl(const Mask& value, const PrintOptions& options) {
    const std::unordered_map<const Node*, std::string> no_names;
    return Printer(options, no_names).print(*value.node()).text;
}

Statements statements(std::span<const Output> outputs, std::span<const Hint> hints,
                      const PrintOptions& options, std::string_view indent) {
    // How many parents (or outputs) use each node.
    std::unordered_map<const Node*, int> uses;
    const auto count = [&](const auto& self, const Node& node) -> void {
        if (++uses[&node] > 1) return;
        for (int i = 0; i < arity(node.op); ++i)
            self(self, *node.args[static_cast<std::size_t>(i)]);
    };
    for (const Output& output : outputs) count(count, *output.value.node());

    std::unordered_map<const Node*, std::string> names;
    std::unordered_set<std::string> taken;
    const auto unique = [&](const std::string& base) {
        std::string name = base;
        for (int k = 1; taken.count(name) != 0; ++k) name = base + "_" + std::to_string(k);
        taken.insert(name);
        return name;
    };
    const auto hint_for = [&](const Node& node) -> const Hint* {
        for (const Hint& hint : hints)
            if (same_structure(node, *hint.pattern.node())) return &hint;
        return nullptr;
    };
    int unnamed = 0;
    const auto next_unnamed = [&] {
        std::string name;
        // std::string("t"): as in Printer.
        do name = std::string("t") + std::to_string(unnamed++);
        while (taken.count(name) != 0);
        return unique(name);
    };

    // Temporaries in dependency order: children before parents.
    const Printer printer(options, names);
    Statements result;
    std::unordered_set<const Node*> visited;
    const auto emit = [&](const auto& self, const Node& node) -> void {
        if (!visited.insert(&node).second) return;
        for (int i = 0; i < arity(node.op); ++i)
            self(self, *node.args[static_cast<std::size_t>(i)]);
        if (is_leaf(node.op)) return;
        const Hint* hint = hint_for(node);
        if (uses[&node] > 1 || hint != nullptr) {
            const std::string definition = printer.print(node).text;
            const std::string name = hint != nullptr ? unique(hint->name) : next_unnamed();
            result.temporaries += std::string(indent) +
                                  (is_comparison(node.op) ? "bool " : "float ") + name + " = " +
                                  definition + ";\n";
            names.emplace(&node, name);
        }
    };
    for (const Output& output : outputs) emit(emit, *output.value.node());

    for (const Output& output : outputs) {
        const std::string value = printer.print(*output.value.node()).text;
        result.assignments +=
            std::string(indent) +
            (output.target.empty() ? "return " + value : output.target + " = " + value) + ";\n";
    }
    return result;
}

std::string print_statements(std::span<const Output> outputs, std::span<const Hint> hints,
                             const PrintOptions& options, std::string_view indent) {
    const Statements printed = statements(outputs, hints, options, indent);
    return printed.temporaries + printed.assignments;
}

// ---- Evaluation ----

namespace {

float evaluate_node(const Node& node, const Bindings& bindings,
                    std::unordered_map<const Node*, float>& memo) {
    if (auto known = memo.find(&node); known != memo.end()) return known->second;
    const auto arg = [&](int i) {
        return evaluate_node(*node.args[static_cast<std::size_t>(i)], bindings, memo);
    };
    float result = 0.0f;
    switch (node.op) {
        case Op::Literal:
            result = node.value;
            break;
        case Op::Variable: {
            const auto bound = bindings.find(node.name);
            if (bound == bindings.end())
                throw std::out_of_range("glsl::evaluate: no value for " + node.name);
            result = bound->second;
            break;
        }
        case Op::Add:
            result = arg(0) + arg(1);
            break;
        case Op::Subtract:
            result = arg(0) - arg(1);
            break;
        case Op::Multiply:
            result = arg(0) * arg(1);
            break;
        case Op::Divide:
            result = arg(0) / arg(1);
            break;
        case Op::Negate:
            result = -arg(0);
            break;
        case Op::Less:
            result = arg(0) < arg(1) ? 1.0f : 0.0f;
            break;
        case Op::LessEqual:
            result = arg(0) <= arg(1) ? 1.0f : 0.0f;
            break;
        case Op::Greater:
            result = arg(0) > arg(1) ? 1.0f : 0.0f;
            break;
        case Op::GreaterEqual:
            result = arg(0) >= arg(1) ? 1.0f : 0.0f;
            break;
        case Op::Select: {
            // Both sides, as equations::select(bool, float, float) receives them.
            const float mask = arg(0);
            const float if_true = arg(1);
            const float if_false = arg(2);
            result = mask != 0.0f ? if_true : if_false;
            break;
        }
        case Op::Max:
            result = equations::max(arg(0), arg(1));
            break;
        case Op::Pow:
            result = std::pow(arg(0), arg(1));
            break;
        case Op::Sqrt:
            result = std::sqrt(arg(0));
            break;
        case Op::Min:
            result = equations::min(arg(0), arg(1));
            break;
        case Op::Floor:
            result = std::floor(arg(0));
            break;
    }
    memo.emplace(&node, result);
    return result;
}

}  // namespace

float evaluate(const Expr& value, const Bindings& bindings) {
    std::unordered_map<const Node*, float> memo;
    return evaluate_node(*value.node(), bindings, memo);
}

bool evaluate(const Mask& value, const Bindings& bindings) {
    std::unordered_map<const Node*, float> memo;
    return evaluate_node(*value.node(), bindings, memo) != 0.0f;
}

}  // namespace litkit::glsl
