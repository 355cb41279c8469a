// SPDX-License-Identifier: MIT
// Tests of the GLSL generator (litkit/glsl.hpp, src/codegen/glsl_expr.hpp):
//   - the expression type Expr and its printing (literals, precedence,
//     builtins, common subexpressions);
//   - the exact text of small generated functions, worked out by hand from
//     litkit/equations.hpp;
//   - that the generated functions mean what the float templates compute, on
//     random and edge-case inputs, both through the expression DAG and
//     through the printed GLSL text (run by a small interpreter below);
//   - that every program compiles and links with glslangValidator.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "../src/codegen/glsl_expr.hpp"
#include "litkit/equations.hpp"
#include "litkit/error.hpp"
#include "litkit/glsl.hpp"
#include "litkit/lighting.hpp"

#ifndef LITKIT_GLSLANG_VALIDATOR
#error "tests/CMakeLists.txt must define LITKIT_GLSLANG_VALIDATOR (find_program glslangValidator)"
#endif

namespace {

using litkit::Reflection;
using litkit::Shading;
using litkit::equations::Vec3;
using litkit::glsl::Bindings;
using litkit::glsl::Expr;
using litkit::glsl::Function;
using litkit::glsl::Hint;
using litkit::glsl::Output;
using litkit::glsl::to_glsl;

constexpr Reflection all_reflections[] = {
    Reflection::Lambert,    Reflection::HalfLambert, Reflection::Phong,
    Reflection::BlinnPhong, Reflection::OrenNayar,   Reflection::CookTorrance,
    Reflection::Toon,       Reflection::Minnaert,    Reflection::Gooch};
static_assert(std::size(all_reflections) == litkit::reflection_count);
constexpr Shading all_shadings[] = {Shading::Flat, Shading::Gouraud, Shading::Phong};

Expr var(const char* name) { return Expr::variable(name); }

// ---------------------------------------------------------------------------
// Expr: printing

TEST(GlslExpr, LiteralsAreFloatLiterals) {
    EXPECT_EQ(litkit::glsl::float_literal(1.0f), "1.0");
    EXPECT_EQ(litkit::glsl::float_literal(0.0f), "0.0");
    EXPECT_EQ(litkit::glsl::float_literal(2.0f), "2.0");
    EXPECT_EQ(litkit::glsl::float_literal(0.5f), "0.5");
    EXPECT_EQ(litkit::glsl::float_literal(-0.25f), "-0.25");
    EXPECT_EQ(litkit::glsl::float_literal(255.0f), "255.0");
    EXPECT_EQ(to_glsl(Expr(1)), "1.0");
    EXPECT_EQ(to_glsl(Expr(0.5f)), "0.5");
}

TEST(GlslExpr, LiteralsReadBackExactly) {
    std::vector<float> values{1e-6f,       0.1f,  1.0f / 3.0f, 3.4028235e38f, 1e-40f,
                              16777217.0f, 1e10f, -7e-12f,     123456.79f,    0.99999994f};
    std::mt19937 random(7);
    std::uniform_int_distribution<int> exponent(-30, 30);
    std::uniform_real_distribution<float> mantissa(-1.0f, 1.0f);
    for (int i = 0; i < 1000; ++i) values.push_back(std::ldexp(mantissa(random), exponent(random)));
    for (float value : values) {
        const std::string text = litkit::glsl::float_literal(value);
        // A GLSL float literal: a '.' or an exponent, never a bare integer.
        EXPECT_NE(text.find_first_of(".e"), std::string::npos) << text;
        EXPECT_EQ(std::strtof(text.c_str(), nullptr), value) << text;
    }
    EXPECT_EQ(litkit::glsl::float_literal(1e-6f), "1e-06");
}

TEST(GlslExpr, NonFiniteLiteralsAreRejected) {
    EXPECT_THROW(litkit::glsl::float_literal(std::numeric_limits<float>::infinity()),
                 litkit::ArgumentError);
    EXPECT_THROW(litkit::glsl::float_literal(std::numeric_limits<float>::quiet_NaN()),
                 litkit::ArgumentError);
}

TEST(GlslExpr, ParenthesesOnlyWherePrecedenceOrOrderNeedsThem) {
    const Expr a = var("a");
    const Expr b = var("b");
    const Expr c = var("c");
    EXPECT_EQ(to_glsl(a - (b - c)), "a - (b - c)");
    EXPECT_EQ(to_glsl((a - b) - c), "a - b - c");
    EXPECT_EQ(to_glsl(a + (b + c)), "a + (b + c)");  // float addition is not associative
    EXPECT_EQ(to_glsl((a + b) + c), "a + b + c");
    EXPECT_EQ(to_glsl((a + b) * c), "(a + b) * c");
    EXPECT_EQ(to_glsl(a + b * c), "a + b * c");
    EXPECT_EQ(to_glsl(a * b + c), "a * b + c");
    EXPECT_EQ(to_glsl(a / (b * c)), "a / (b * c)");
    EXPECT_EQ(to_glsl(a * b / c), "a * b / c");
    EXPECT_EQ(to_glsl(a * (b / c)), "a * (b / c)");
    EXPECT_EQ(to_glsl(Expr(1.0f) / (a + b)), "1.0 / (a + b)");
    EXPECT_EQ(to_glsl(-a), "-a");
    EXPECT_EQ(to_glsl(-(a + b)), "-(a + b)");
    EXPECT_EQ(to_glsl(-(a * b)), "-(a * b)");
    EXPECT_EQ(to_glsl(-(-a)), "-(-a)");  // never the decrement token
    EXPECT_EQ(to_glsl(-a * b), "-a * b");
    EXPECT_EQ(to_glsl(a * -b), "a * -b");
    EXPECT_EQ(to_glsl(a - -b), "a - -b");
    EXPECT_EQ(to_glsl(a - Expr(-1.0f)), "a - -1.0");
    EXPECT_EQ(to_glsl(Expr(-2.0f) * a), "-2.0 * a");
    EXPECT_EQ(to_glsl(-Expr(-2.0f)), "-(-2.0)");
}

TEST(GlslExpr, ComparisonsSelectAndBuiltins) {
    const Expr a = var("a");
    const Expr b = var("b");
    EXPECT_EQ(to_glsl(a < b), "a < b");
    EXPECT_EQ(to_glsl(a <= b), "a <= b");
    EXPECT_EQ(to_glsl(a > b + b), "a > b + b");
    EXPECT_EQ(to_glsl(a * b >= -a), "a * b >= -a");
    EXPECT_EQ(to_glsl(select(a >= b, max(a, Expr(0)), pow(a, b))),
              "(a >= b ? max(a, 0.0) : pow(a, b))");
    EXPECT_EQ(to_glsl(sqrt(a * a + b * b)), "sqrt(a * a + b * b)");
    EXPECT_EQ(to_glsl(Expr(2) * select(a > b, a, b)), "2.0 * (a > b ? a : b)");
    EXPECT_EQ(to_glsl(-sqrt(a)), "-sqrt(a)");
    litkit::glsl::PrintOptions options;
    options.pow_function = "power";
    EXPECT_EQ(to_glsl(pow(a, b), options), "power(a, b)");
}

TEST(GlslExpr, SharedNodesBecomeTemporariesInDependencyOrder) {
    const Expr a = var("a");
    const Expr b = var("b");
    const Expr sum = a + b;         // used twice
    const Expr square = sum * sum;  // used twice
    const Expr once = a * b;        // used once
    const std::vector<Output> outputs{{"x", square + once}, {"y", square - Expr(1)}};
    EXPECT_EQ(litkit::glsl::print_statements(outputs),
              "    float t0 = a + b;\n"
              "    float t1 = t0 * t0;\n"
              "    x = t1 + a * b;\n"
              "    y = t1 - 1.0;\n");
    // Leaves used twice stay inline; a single use is inlined.
    const std::vector<Output> single{{"z", a * a + (b - a)}};
    EXPECT_EQ(litkit::glsl::print_statements(single, {}, {}, ""), "z = a * a + (b - a);\n");
    // Shared masks are bool temporaries; `return` for an empty target.
    const litkit::glsl::Mask positive = a > Expr(0);
    const std::vector<Output> masked{{"", select(positive, a, b) + select(positive, b, a)}};
    EXPECT_EQ(litkit::glsl::print_statements(masked, {}, {}, ""),
              "bool t0 = a > 0.0;\n"
              "return (t0 ? a : b) + (t0 ? b : a);\n");
}

TEST(GlslExpr, HintsNameTemporariesEvenForOneUse) {
    const Expr a = var("a");
    const Expr b = var("b");
    const Expr sum = a + b;
    const std::vector<Output> outputs{{"x", sum * sum + a * b}};
    // The hint is another node of the same structure, as the generator builds them.
    const std::vector<Hint> hints{{"total", a + b}, {"product", a * b}, {"unused", a - b}};
    EXPECT_EQ(litkit::glsl::print_statements(outputs, hints, {}, ""),
              "float total = a + b;\n"
              "float product = a * b;\n"
              "x = total * total + product;\n");
}

TEST(GlslExpr, EvaluateFollowsTheFloatOperations) {
    const Expr a = var("a");
    const Expr b = var("b");
    const Bindings bindings{{"a", 3.0f}, {"b", -2.0f}};
    EXPECT_EQ(evaluate(a - (b - a), bindings), 3.0f - (-2.0f - 3.0f));
    EXPECT_EQ(evaluate(select(a > b, max(b, Expr(0)), a), bindings), 0.0f);
    EXPECT_EQ(evaluate(pow(a, -b) / sqrt(a), bindings), std::pow(3.0f, 2.0f) / std::sqrt(3.0f));
    EXPECT_TRUE(evaluate(a >= a, bindings));
    EXPECT_FALSE(evaluate(a < b, bindings));
    EXPECT_THROW(evaluate(var("c"), bindings), std::out_of_range);
}

// ---------------------------------------------------------------------------
// Generated functions: exact text

std::string printed(const Function& function) {
    return litkit::glsl::print_function(function, litkit::glsl::shader_print_options());
}

TEST(GlslFunctions, DirectionalIncidenceText) {
    // return {-travel_unit, T(1)};
    EXPECT_EQ(printed(litkit::glsl::directional_incidence_function()),
              "// Directional light: L = -normalize(direction), f = 1.\n"
              "// travel_unit: the normalised direction the light travels.\n"
              "Incidence directional_incidence(vec3 travel_unit) {\n"
              "    Incidence result;\n"
              "    result.to_light.x = -travel_unit.x;\n"
              "    result.to_light.y = -travel_unit.y;\n"
              "    result.to_light.z = -travel_unit.z;\n"
              "    result.factor = 1.0;\n"
              "    return result;\n"
              "}\n");
}

TEST(GlslFunctions, SpotFactorText) {
    // T c = -dot(to_light, axis_unit);
    // T width = cos_inner - cos_cutoff;
    // T t = (c - cos_cutoff) / select(width > T(0), width, T(1));
    // T w = select(c >= cos_inner - T(slack), T(1), t * t * (T(3) - T(2) * t));
    // return select(c >= cos_cutoff - T(slack), pow(max(c, T(0)), exponent) * w, T(0));
    const std::string text = printed(litkit::glsl::spot_factor_function());
    const std::string body =
        "float spot_factor(vec3 to_light, vec3 axis_unit, float cos_cutoff, float cos_inner, "
        "float exponent) {\n"
        "    float c = -(to_light.x * axis_unit.x + to_light.y * axis_unit.y + to_light.z * "
        "axis_unit.z);\n"
        "    float t0 = cos_inner - cos_cutoff;\n"
        "    float t1 = (c - cos_cutoff) / (t0 > 0.0 ? t0 : 1.0);\n"
        "    return (c >= cos_cutoff - 1e-06 ? power(max(c, 0.0), exponent) * (c >= cos_inner - "
        "1e-06 ? 1.0 : t1 * t1 * (3.0 - 2.0 * t1)) : 0.0);\n"
        "}\n";
    ASSERT_GE(text.size(), body.size());
    EXPECT_EQ(text.substr(text.size() - body.size()), body);
    EXPECT_EQ(text.rfind("// ", 0), 0u) << "a doc comment comes first";
}

TEST(GlslFunctions, PointIncidenceText) {
    // to_light = light_position - p; distance = length(to_light);
    // {(1 / distance) * to_light, 1 / (k.x + k.y * distance + k.z * distance * distance)}
    const std::string text = printed(litkit::glsl::point_incidence_function());
    const std::string body =
        "Incidence point_incidence(vec3 light_position, vec3 attenuation, vec3 p) {\n"
        "    float to_light_x = light_position.x - p.x;\n"
        "    float to_light_y = light_position.y - p.y;\n"
        "    float to_light_z = light_position.z - p.z;\n"
        "    float light_distance = sqrt(to_light_x * to_light_x + to_light_y * to_light_y + "
        "to_light_z * to_light_z);\n"
        "    float inv_distance = 1.0 / light_distance;\n"
        "    Incidence result;\n"
        "    result.to_light.x = inv_distance * to_light_x;\n"
        "    result.to_light.y = inv_distance * to_light_y;\n"
        "    result.to_light.z = inv_distance * to_light_z;\n"
        "    result.factor = 1.0 / (attenuation.x + attenuation.y * light_distance + "
        "attenuation.z * light_distance * light_distance);\n"
        "    return result;\n"
        "}\n";
    ASSERT_GE(text.size(), body.size());
    EXPECT_EQ(text.substr(text.size() - body.size()), body);
}

TEST(GlslFunctions, AmbientAndDirectTermText) {
    // material.ka * (material.color * radiance): the product on the right stays
    // grouped (float multiplication is not associative).
    EXPECT_NE(printed(litkit::glsl::ambient_term_function())
                  .find("    vec3 result;\n"
                        "    result.x = material.ka * (material.color.x * radiance.x);\n"
                        "    result.y = material.ka * (material.color.y * radiance.y);\n"
                        "    result.z = material.ka * (material.color.z * radiance.z);\n"
                        "    return result;\n"),
              std::string::npos);
    // specular = ks * S; factor * (radiance * (diffuse colour + specular)).
    EXPECT_NE(printed(litkit::glsl::direct_term_function())
                  .find("    float specular = material.ks * reflected.specular;\n"
                        "    vec3 result;\n"
                        "    result.x = factor * (radiance.x * (reflected.diffuse * "
                        "reflected.color.x + specular));\n"),
              std::string::npos);
}

TEST(GlslFunctions, PhongReflectionTermsOperations) {
    const std::string text = printed(litkit::glsl::reflection_terms_function(Reflection::Phong));
    for (const char* expected : {
             "Reflected reflect_light(vec3 normal, vec3 to_light, vec3 to_eye, Material material) "
             "{\n",
             "    float n_dot_l = normal.x * to_light.x + normal.y * to_light.y + normal.z * "
             "to_light.z;\n",
             "    float two_n_dot_l = 2.0 * n_dot_l;\n",
             "    float reflected_x = two_n_dot_l * normal.x - to_light.x;\n",
             "    float reflected_z = two_n_dot_l * normal.z - to_light.z;\n",
             "    float r_dot_v = reflected_x * to_eye.x + reflected_y * to_eye.y + reflected_z * "
             "to_eye.z;\n",
             "    result.diffuse = material.kd * max(n_dot_l, 0.0);\n",
             "    result.color.x = material.color.x;\n",
             "    result.specular = (n_dot_l > 0.0 ? (r_dot_v > 0.0 ? power(max(r_dot_v, 0.0), "
             "material.shininess) : 0.0) : 0.0);\n",
         }) {
        EXPECT_NE(text.find(expected), std::string::npos) << "missing: " << expected << "in\n"
                                                          << text;
    }
}

TEST(GlslFunctions, BlinnPhongReflectionTermsOperations) {
    const std::string text =
        printed(litkit::glsl::reflection_terms_function(Reflection::BlinnPhong));
    for (const char* expected : {
             "    float l_plus_v_x = to_light.x + to_eye.x;\n",
             "    float inv_l_plus_v_length = 1.0 / l_plus_v_length;\n",
             "    float halfway_y = inv_l_plus_v_length * l_plus_v_y;\n",
             "    float n_dot_h = normal.x * halfway_x + normal.y * halfway_y + normal.z * "
             "halfway_z;\n",
             "    result.specular = (n_dot_l > 0.0 ? (n_dot_h > 0.0 ? power(max(n_dot_h, 0.0), "
             "material.shininess) : 0.0) : 0.0);\n",
         }) {
        EXPECT_NE(text.find(expected), std::string::npos) << "missing: " << expected << "in\n"
                                                          << text;
    }
}

// ---------------------------------------------------------------------------
// A small interpreter for the printed function bodies: float temporaries,
// assignments and return, over + - * /, unary -, comparisons, ?: and the
// calls max, pow, power, sqrt, each evaluated in float as the CPU path does.

class GlslInterpreter {
  public:
    // The values of the outputs ("result.to_light.x", or "" for `return`)
    // of the function printed in `source`, with parameters bound as given.
    static std::map<std::string, float> run(const std::string& source, const Bindings& bindings) {
        GlslInterpreter interpreter(bindings);
        std::istringstream lines(source);
        std::string line;
        bool in_body = false;
        std::map<std::string, float> outputs;
        while (std::getline(lines, line)) {
            if (!in_body) {
                in_body = !line.empty() && line.back() == '{';
                continue;
            }
            if (line == "}") break;
            interpreter.statement(line, outputs);
        }
        return outputs;
    }

  private:
    explicit GlslInterpreter(const Bindings& bindings) : bindings_(bindings) {}

    // One line of a printed body: `float|bool NAME = EXPR;`, `TYPE result;`,
    // `return result;`, `return EXPR;` or `TARGET = EXPR;`.
    void statement(std::string line, std::map<std::string, float>& outputs) {
        line.erase(0, line.find_first_not_of(' '));
        if (line.empty() || line.back() != ';')
            throw std::runtime_error("interpreter: unknown statement: " + line);
        line.pop_back();
        const std::size_t space = line.find(' ');
        const std::string first = line.substr(0, space);
        const std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
        const std::size_t equals = line.find(" = ");
        if (rest == "result") return;  // `T result;` and `return result;`
        if (first == "return") {
            outputs[""] = expression(rest);
        } else if (equals == std::string::npos) {
            throw std::runtime_error("interpreter: unknown statement: " + line);
        } else if (first == "float" || first == "bool") {
            locals_[line.substr(space + 1, equals - space - 1)] =
                expression(line.substr(equals + 3));
        } else {
            outputs[line.substr(0, equals)] = expression(line.substr(equals + 3));
        }
    }

    float expression(const std::string& text) {
        text_ = text;
        position_ = 0;
        const float value = ternary();
        skip_space();
        if (position_ != text_.size())
            throw std::runtime_error("interpreter: trailing text in " + text_);
        return value;
    }

    void skip_space() {
        while (position_ < text_.size() && text_[position_] == ' ') ++position_;
    }
    bool accept(std::string_view token) {
        skip_space();
        if (text_.compare(position_, token.size(), token) != 0) return false;
        position_ += token.size();
        return true;
    }
    void expect(std::string_view token) {
        if (!accept(token))
            throw std::runtime_error("interpreter: expected " + std::string(token) + " at " +
                                     std::to_string(position_) + " in " + text_);
    }

    float ternary() {
        const float condition = relational();
        if (!accept("?")) return condition;
        const float if_true = ternary();
        expect(":");
        const float if_false = ternary();
        return condition != 0.0f ? if_true : if_false;
    }
    float relational() {
        const float left = additive();
        if (accept("<=")) return left <= additive() ? 1.0f : 0.0f;
        if (accept(">=")) return left >= additive() ? 1.0f : 0.0f;
        if (accept("<")) return left < additive() ? 1.0f : 0.0f;
        if (accept(">")) return left > additive() ? 1.0f : 0.0f;
        return left;
    }
    float additive() {
        float value = multiplicative();
        for (;;) {
            if (accept("+")) {
                value = value + multiplicative();
            } else if (accept("-")) {
                value = value - multiplicative();
            } else {
                return value;
            }
        }
    }
    float multiplicative() {
        float value = unary();
        for (;;) {
            if (accept("*")) {
                value = value * unary();
            } else if (accept("/")) {
                value = value / unary();
            } else {
                return value;
            }
        }
    }
    float unary() {
        if (accept("-")) return -unary();
        return primary();
    }
    float primary() {
        skip_space();
        if (accept("(")) {
            const float value = ternary();
            expect(")");
            return value;
        }
        const std::size_t start = position_;
        if (position_ < text_.size() &&
            std::isdigit(static_cast<unsigned char>(text_[position_]))) {
            char* end = nullptr;
            const float value = std::strtof(text_.c_str() + start, &end);
            position_ = static_cast<std::size_t>(end - text_.c_str());
            return value;
        }
        while (position_ < text_.size() &&
               (std::isalnum(static_cast<unsigned char>(text_[position_])) ||
                text_[position_] == '_' || text_[position_] == '.'))
            ++position_;
        const std::string name = text_.substr(start, position_ - start);
        if (name.empty()) throw std::runtime_error("interpreter: unexpected text in " + text_);
        if (accept("(")) {
            std::vector<float> args{ternary()};
            while (accept(",")) args.push_back(ternary());
            expect(")");
            if (name == "max" && args.size() == 2) return args[0] > args[1] ? args[0] : args[1];
            if ((name == "pow" || name == "power") && args.size() == 2)
                return std::pow(args[0], args[1]);
            if (name == "sqrt" && args.size() == 1) return std::sqrt(args[0]);
            if (name == "min" && args.size() == 2) return args[0] < args[1] ? args[0] : args[1];
            if (name == "floor" && args.size() == 1) return std::floor(args[0]);
            throw std::runtime_error("interpreter: unknown function " + name);
        }
        if (auto local = locals_.find(name); local != locals_.end()) return local->second;
        if (auto bound = bindings_.find(name); bound != bindings_.end()) return bound->second;
        throw std::runtime_error("interpreter: unbound name " + name);
    }

    const Bindings& bindings_;
    std::map<std::string, float> locals_;
    std::string text_;
    std::size_t position_ = 0;
};

TEST(GlslInterpreter, EvaluatesPrecedenceAsGlsl) {
    const auto outputs = GlslInterpreter::run(
        "f() {\n    float t = 1.0 - (2.0 - 4.0) * -x;\n    return (t >= 0.0 ? max(t, 1.0) : "
        "sqrt(power(4.0, 2.0)));\n}\n",
        Bindings{{"x", 2.0f}});
    EXPECT_EQ(outputs.at(""), 4.0f);  // t = 1 - (-2)(-2) = -3 < 0 → sqrt(16)
}

// ---------------------------------------------------------------------------
// Generated functions: the same values as the float templates

bool same_value(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    return std::abs(a - b) <= 1e-6f * std::max(std::abs(a), std::abs(b));
}

void set_input(Bindings& bindings, const std::string& name, const Vec3<float>& value) {
    bindings[name + ".x"] = value.x;
    bindings[name + ".y"] = value.y;
    bindings[name + ".z"] = value.z;
}

void set_input(Bindings& bindings, const std::string& name,
               const litkit::equations::MaterialT<float>& material) {
    set_input(bindings, name + ".color", material.color);
    bindings[name + ".ka"] = material.ka;
    bindings[name + ".kd"] = material.kd;
    bindings[name + ".ks"] = material.ks;
    bindings[name + ".shininess"] = material.shininess;
    bindings[name + ".sigma"] = material.sigma;
    bindings[name + ".roughness"] = material.roughness;
    bindings[name + ".f0"] = material.f0;
    bindings[name + ".bands"] = material.bands;
    bindings[name + ".minnaert_k"] = material.minnaert_k;
}

std::string describe(const Bindings& bindings) {
    std::string text;
    for (const auto& [name, value] : bindings) text += " " + name + "=" + std::to_string(value);
    return text;
}

// The outputs of `function` for `bindings`, through the DAG and through the
// printed text, against `expected` (in the order of function.outputs).
void expect_values(const Function& function, const Bindings& bindings,
                   const std::vector<float>& expected) {
    ASSERT_EQ(function.outputs.size(), expected.size());
    const auto from_text = GlslInterpreter::run(printed(function), bindings);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const Output& output = function.outputs[i];
        const float from_dag = evaluate(output.value, bindings);
        EXPECT_PRED2(same_value, from_dag, expected[i])
            << function.name << " " << output.target << " (DAG) at" << describe(bindings);
        ASSERT_EQ(from_text.count(output.target), 1u) << output.target;
        EXPECT_PRED2(same_value, from_text.at(output.target), expected[i])
            << function.name << " " << output.target << " (text) at" << describe(bindings);
    }
}

class Inputs {
  public:
    float uniform(float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(random_);
    }
    Vec3<float> vector(float extent) {
        return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
    }
    Vec3<float> unit() {
        for (;;) {
            const Vec3<float> v = vector(1.0f);
            const float length = litkit::equations::length(v);
            if (length > 0.1f && length <= 1.0f) return litkit::equations::normalize(v);
        }
    }
    // Exactly 0 a quarter of the time, else as given.
    float sometimes_zero(float value) { return uniform(0.0f, 1.0f) < 0.25f ? 0.0f : value; }

  private:
    std::mt19937 random_{20240611};
};

constexpr int random_cases = 300;

TEST(GlslNumeric, DirectionalIncidence) {
    const Function function = litkit::glsl::directional_incidence_function();
    Inputs inputs;
    for (int i = 0; i < random_cases; ++i) {
        const Vec3<float> travel = inputs.unit();
        const auto incidence = litkit::equations::directional_incidence(travel);
        Bindings bindings;
        set_input(bindings, "travel_unit", travel);
        expect_values(
            function, bindings,
            {incidence.to_light.x, incidence.to_light.y, incidence.to_light.z, incidence.factor});
    }
}

TEST(GlslNumeric, PointIncidence) {
    const Function function = litkit::glsl::point_incidence_function();
    Inputs inputs;
    const Vec3<float> fixed_attenuations[] = {{0, 0, 1}, {1, 0, 0}, {1, 0.09f, 0.032f}};
    for (int i = 0; i < random_cases; ++i) {
        const Vec3<float> light = inputs.vector(10.0f);
        const Vec3<float> p = inputs.vector(10.0f);
        const Vec3<float> attenuation =
            i % 4 < 3
                ? fixed_attenuations[i % 4]
                : Vec3<float>{inputs.uniform(0, 2), inputs.uniform(0, 2), inputs.uniform(0, 2)};
        const auto incidence = litkit::equations::point_incidence(light, attenuation, p);
        Bindings bindings;
        set_input(bindings, "light_position", light);
        set_input(bindings, "attenuation", attenuation);
        set_input(bindings, "p", p);
        expect_values(
            function, bindings,
            {incidence.to_light.x, incidence.to_light.y, incidence.to_light.z, incidence.factor});
    }
}

TEST(GlslNumeric, SpotFactor) {
    const Function function = litkit::glsl::spot_factor_function();
    Inputs inputs;
    // cos_inner = cos_cutoff: a spot without penumbra (docs/spec.md §4);
    // check_soft passes another inner cone (§9.3).
    auto check_soft = [&](const Vec3<float>& to_light, const Vec3<float>& axis, float cos_cutoff,
                          float cos_inner, float exponent) {
        const float expected =
            litkit::equations::spot_factor(to_light, axis, cos_cutoff, cos_inner, exponent);
        Bindings bindings;
        set_input(bindings, "to_light", to_light);
        set_input(bindings, "axis_unit", axis);
        bindings["cos_cutoff"] = cos_cutoff;
        bindings["cos_inner"] = cos_inner;
        bindings["exponent"] = exponent;
        expect_values(function, bindings, {expected});
        return expected;
    };
    auto check = [&](const Vec3<float>& to_light, const Vec3<float>& axis, float cos_cutoff,
                     float exponent) {
        return check_soft(to_light, axis, cos_cutoff, cos_cutoff, exponent);
    };
    for (int i = 0; i < random_cases; ++i) {
        const Vec3<float> to_light = inputs.unit();
        const Vec3<float> axis = inputs.unit();
        const float cos_cutoff = inputs.uniform(-1.0f, 1.0f);
        check_soft(to_light, axis, cos_cutoff, inputs.uniform(cos_cutoff, 1.0f),
                   inputs.sometimes_zero(inputs.uniform(0.0f, 64.0f)));
    }
    for (int i = 0; i < random_cases; ++i) {
        const Vec3<float> to_light = inputs.unit();
        const Vec3<float> axis = inputs.unit();
        const float exponent = inputs.sometimes_zero(inputs.uniform(0.0f, 64.0f));
        // Every third case exactly on the cone: c == cos(cutoff), inside.
        const float c = -litkit::equations::dot(to_light, axis);
        const float cos_cutoff = i % 3 == 0 ? c : inputs.uniform(-1.0f, 1.0f);
        const float s = check(to_light, axis, cos_cutoff, exponent);
        if (i % 3 == 0) {
            EXPECT_EQ(s, std::pow(std::max(c, 0.0f), exponent)) << "on the cone, inside";
        }
    }
    // c = 0 exactly (L across the axis), a 90 degree cone, exponent 0: 0^0 = 1.
    EXPECT_EQ(check({1, 0, 0}, {0, -1, 0}, -1e-6f, 0.0f), 1.0f);
    EXPECT_EQ(check({1, 0, 0}, {0, -1, 0}, -1e-6f, 2.0f), 0.0f);
    // Straight down the axis, and outside the cone.
    EXPECT_EQ(check({0, 1, 0}, {0, -1, 0}, 0.5f, 0.0f), 1.0f);
    EXPECT_EQ(check({0, -1, 0}, {0, -1, 0}, 0.5f, 1.0f), 0.0f);
}

class GlslNumericReflection : public testing::TestWithParam<Reflection> {};

TEST_P(GlslNumericReflection, ReflectionTerms) {
    const Reflection reflection = GetParam();
    const Function function = litkit::glsl::reflection_terms_function(reflection);
    Inputs inputs;
    auto check = [&](const Vec3<float>& normal, const Vec3<float>& to_light,
                     const Vec3<float>& to_eye, float shininess) {
        // The other parameters at random within their ranges (docs/spec.md §9.1),
        // sometimes at an end.
        litkit::Material source;
        source.color = {inputs.uniform(0, 1), inputs.uniform(0, 1), inputs.uniform(0, 1)};
        source.kd = inputs.uniform(0, 1);
        source.shininess = shininess;
        source.sigma = inputs.sometimes_zero(inputs.uniform(0, 90));
        source.roughness = inputs.sometimes_zero(inputs.uniform(0, 1));
        source.f0 = inputs.uniform(0, 1);
        source.bands = 2 + static_cast<int>(inputs.uniform(0, 14.99f));
        source.minnaert_k = inputs.sometimes_zero(inputs.uniform(0, 4));
        const auto material = litkit::equations::splat<float>(source);
        const auto reflected = litkit::equations::with_reflection(reflection, [&](auto model) {
            return litkit::equations::reflect<decltype(model)::value>(normal, to_light, to_eye,
                                                                      material);
        });
        Bindings bindings;
        set_input(bindings, "normal", normal);
        set_input(bindings, "to_light", to_light);
        set_input(bindings, "to_eye", to_eye);
        set_input(bindings, "material", material);
        expect_values(function, bindings,
                      {reflected.diffuse, reflected.color.x, reflected.color.y, reflected.color.z,
                       reflected.specular});
    };
    const float shininesses[] = {0.0f, 1.0f, 32.0f, 0.5f};
    for (int i = 0; i < random_cases; ++i) {
        // Random unit vectors: N.L < 0 about half the time.
        const float shininess = i % 5 < 4 ? shininesses[i % 5] : inputs.uniform(0.0f, 200.0f);
        check(inputs.unit(), inputs.unit(), inputs.unit(), shininess);
    }
    const Vec3<float> up{0, 1, 0};
    const Vec3<float> across{1, 0, 0};
    const Vec3<float> down{0, -1, 0};
    for (float shininess : shininesses) {
        check(up, across, up, shininess);  // N.L = 0 exactly
        check(up, down, up, shininess);    // N.L < 0
        check(up, up, up, shininess);      // L = V = N
        check(up, up, down, shininess);    // R.V < 0, N.H = 0
        check(up, across, across, shininess);
    }
}

INSTANTIATE_TEST_SUITE_P(AllModels, GlslNumericReflection, testing::ValuesIn(all_reflections),
                         [](const testing::TestParamInfo<Reflection>& info) {
                             std::string name(litkit::to_string(info.param));
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

TEST(GlslNumeric, AmbientAndDirectTerms) {
    const Function ambient = litkit::glsl::ambient_term_function();
    const Function direct = litkit::glsl::direct_term_function();
    Inputs inputs;
    for (int i = 0; i < random_cases; ++i) {
        const Vec3<float> radiance{inputs.uniform(0, 3), inputs.uniform(0, 3),
                                   inputs.uniform(0, 3)};
        litkit::Material source;
        source.color = {inputs.uniform(0, 1), inputs.uniform(0, 1), inputs.uniform(0, 1)};
        source.ka = inputs.uniform(0, 1);
        source.kd = inputs.uniform(0, 1);
        source.ks = inputs.uniform(0, 1);
        source.shininess = inputs.uniform(0, 100);
        const auto material = litkit::equations::splat<float>(source);
        const litkit::equations::Reflected<float> reflected{
            inputs.sometimes_zero(inputs.uniform(0, 1)),
            {inputs.uniform(0, 1), inputs.uniform(0, 1), inputs.uniform(0, 1)},
            inputs.sometimes_zero(inputs.uniform(0, 1))};
        const float factor = inputs.uniform(0, 2);
        Bindings bindings;
        set_input(bindings, "radiance", radiance);
        set_input(bindings, "material", material);
        const auto a = litkit::equations::ambient_term(radiance, material);
        expect_values(ambient, bindings, {a.x, a.y, a.z});
        bindings["factor"] = factor;
        bindings["reflected.diffuse"] = reflected.diffuse;
        set_input(bindings, "reflected.color", reflected.color);
        bindings["reflected.specular"] = reflected.specular;
        const auto d = litkit::equations::direct_term(radiance, factor, reflected, material);
        expect_values(direct, bindings, {d.x, d.y, d.z});
    }
}

TEST(GlslNumeric, UnitVector) {
    const Function function = litkit::glsl::unit_vector_function();
    Inputs inputs;
    for (int i = 0; i < random_cases; ++i) {
        const Vec3<float> v = inputs.vector(i % 2 == 0 ? 1e-3f : 100.0f);
        const auto u = litkit::equations::normalize(v);
        Bindings bindings;
        set_input(bindings, "v", v);
        expect_values(function, bindings, {u.x, u.y, u.z});
    }
}

// ---------------------------------------------------------------------------
// Programs

TEST(GlslGenerate, RejectsACapacityBelowOne) {
    EXPECT_THROW(litkit::glsl::generate(Reflection::Phong, Shading::Phong, 0),
                 litkit::ArgumentError);
    EXPECT_THROW(litkit::glsl::generate(Reflection::Lambert, Shading::Flat, -3),
                 litkit::ArgumentError);
}

TEST(GlslGenerate, EachReflectionModelHasItsOwnTerms) {
    std::set<std::string> fragments;
    for (Reflection reflection : all_reflections)
        fragments.insert(litkit::glsl::generate(reflection, Shading::Phong, 4).fragment);
    EXPECT_EQ(fragments.size(), std::size(all_reflections));
}

// A fresh temporary directory, removed at the end of the test.
class TemporaryDirectory {
  public:
    TemporaryDirectory() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "litkit-glsl-XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TemporaryDirectory() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

struct CommandResult {
    int exit_code;
    std::string output;  // stdout and stderr
};

CommandResult run_command(const std::string& command) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return {-1, "popen failed"};
    std::string output;
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

std::string shell_quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

std::string with_line_numbers(const std::string& source) {
    std::istringstream lines(source);
    std::string line;
    std::string text;
    for (int number = 1; std::getline(lines, line); ++number)
        text += std::to_string(number) + ": " + line + "\n";
    return text;
}

// The `out` variables of the vertex shader or the `in` variables of the
// fragment shader that start with v_, with their qualifiers, as
// "[flat ]vec3 v_name".
std::set<std::string> varyings(const std::string& source, const std::string& direction) {
    std::set<std::string> found;
    std::istringstream lines(source);
    std::string line;
    while (std::getline(lines, line)) {
        std::string qualifier;
        if (line.rfind("flat ", 0) == 0) {
            qualifier = "flat ";
            line.erase(0, qualifier.size());
        }
        if (line.rfind(direction + " ", 0) != 0 || line.back() != ';') continue;
        const std::string declaration = line.substr(direction.size() + 1);  // "vec3 v_x;"
        if (declaration.find(" v_") == std::string::npos) continue;
        found.insert(qualifier + declaration.substr(0, declaration.size() - 1));
    }
    return found;
}

using ProgramParam = std::tuple<Reflection, Shading, int>;

class GlslProgram : public testing::TestWithParam<ProgramParam> {};

TEST_P(GlslProgram, CompilesAndLinksWithGlslangValidator) {
    const std::string validator = LITKIT_GLSLANG_VALIDATOR;
    ASSERT_FALSE(validator.empty())
        << "glslangValidator was not found when the build was configured: run "
           "scripts/install-deps.sh (it installs glslang-tools), then configure again";
    const auto [reflection, shading, capacity] = GetParam();
    const litkit::glsl::Shaders shaders = litkit::glsl::generate(reflection, shading, capacity);

    TemporaryDirectory directory;
    const std::filesystem::path vertex = directory.path() / "program.vert";
    const std::filesystem::path fragment = directory.path() / "program.frag";
    std::ofstream(vertex) << shaders.vertex;
    std::ofstream(fragment) << shaders.fragment;

    const CommandResult vertex_result =
        run_command(shell_quoted(validator) + " " + shell_quoted(vertex));
    EXPECT_EQ(vertex_result.exit_code, 0) << vertex_result.output << "\nvertex shader:\n"
                                          << with_line_numbers(shaders.vertex);
    const CommandResult fragment_result =
        run_command(shell_quoted(validator) + " " + shell_quoted(fragment));
    EXPECT_EQ(fragment_result.exit_code, 0) << fragment_result.output << "\nfragment shader:\n"
                                            << with_line_numbers(shaders.fragment);
    const CommandResult link = run_command(shell_quoted(validator) + " -l " + shell_quoted(vertex) +
                                           " " + shell_quoted(fragment));
    EXPECT_EQ(link.exit_code, 0) << link.output;
}

TEST_P(GlslProgram, FollowsTheInterface) {
    const auto [reflection, shading, capacity] = GetParam();
    const litkit::glsl::Shaders shaders = litkit::glsl::generate(reflection, shading, capacity);
    for (const std::string* source : {&shaders.vertex, &shaders.fragment}) {
        EXPECT_EQ(source->rfind("#version 330 core\n", 0), 0u);
        EXPECT_NE(source->find("Regenerate it with `litkit export`"), std::string::npos);
        for (unsigned char c : *source) {
            ASSERT_TRUE(c == '\n' || (c >= 0x20 && c < 0x7f)) << "not printable ASCII: " << int{c};
        }
    }
    // glslangValidator does not check that interpolation qualifiers agree.
    EXPECT_EQ(varyings(shaders.vertex, "out"), varyings(shaders.fragment, "in"));
    EXPECT_FALSE(varyings(shaders.vertex, "out").empty());

    EXPECT_NE(shaders.vertex.find("gl_Position = u_view_projection * vec4(a_position, 1.0);"),
              std::string::npos);
    EXPECT_NE(shaders.fragment.find("out vec4 frag_color;"), std::string::npos);
    EXPECT_NE(shaders.fragment.find("uniform float u_inv_gamma;"), std::string::npos);
    // The lighting goes into the stage that lights, and only there.
    const std::string& lit = shading == Shading::Phong ? shaders.fragment : shaders.vertex;
    const std::string& unlit = shading == Shading::Phong ? shaders.vertex : shaders.fragment;
    for (const char* declaration :
         {"Reflected reflect_light(", "vec3 shade(vec3 p, vec3 normal, vec3 to_eye)",
          "uniform Light u_lights[MAX_LIGHTS];", "uniform Material u_material;"}) {
        EXPECT_NE(lit.find(declaration), std::string::npos) << declaration;
        EXPECT_EQ(unlit.find(declaration), std::string::npos) << declaration;
    }
    EXPECT_NE(lit.find("const int MAX_LIGHTS = " + std::to_string(capacity) + ";\n"),
              std::string::npos);
    EXPECT_NE(lit.find(printed(litkit::glsl::reflection_terms_function(reflection))),
              std::string::npos);
    EXPECT_EQ(shaders.vertex.find("layout(location = 2) in vec3 a_centroid;") != std::string::npos,
              shading == Shading::Flat);
}

INSTANTIATE_TEST_SUITE_P(AllPrograms, GlslProgram,
                         testing::Combine(testing::ValuesIn(all_reflections),
                                          testing::ValuesIn(all_shadings), testing::Values(1, 8)),
                         [](const testing::TestParamInfo<ProgramParam>& info) {
                             std::string name =
                                 std::string(litkit::to_string(std::get<0>(info.param))) + "_" +
                                 std::string(litkit::to_string(std::get<1>(info.param))) + "_" +
                                 std::to_string(std::get<2>(info.param));
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

}  // namespace

// Anti-aliasing's programs (docs/spec.md §11) write a sample's clamped linear
// light: the pixel programs but for the output function and what the
// heading says of it, in every shading; they compile and link, in ASCII.
TEST(GlslGenerate, SampleLightProgramsDifferOnlyInTheirOutput) {
    const std::string validator = LITKIT_GLSLANG_VALIDATOR;
    ASSERT_FALSE(validator.empty()) << "run scripts/install-deps.sh (glslang-tools)";
    for (const Shading shading :
         {Shading::Flat, Shading::Gouraud, Shading::Phong, Shading::Faceted}) {
        SCOPED_TRACE(std::string(litkit::to_string(shading)));
        const litkit::Light lights[] = {litkit::Light{litkit::PointLight{}}};
        const litkit::glsl::Shaders pixel =
            litkit::glsl::generate(Reflection::Phong, shading, lights, 2.2f);
        const litkit::glsl::Shaders sample = litkit::glsl::generate(
            Reflection::Phong, shading, lights, 2.2f, litkit::glsl::FragmentOutput::SampleLight);
        EXPECT_NE(sample.fragment.find("vec3 sample_light(vec3 intensity) {\n"
                                       "    return mix(vec3(0.0), min(intensity, vec3(1.0)), "
                                       "greaterThan(intensity, vec3(0.0)));\n}\n"),
                  std::string::npos);
        EXPECT_EQ(sample.fragment.find("to_pixel("), std::string::npos);
        EXPECT_EQ(sample.fragment.find("u_inv_gamma"), std::string::npos);
        // Everything after the heading, with the output function's name and
        // definition swapped, is the pixel program's.
        auto body = [](std::string text, const std::string& function) {
            text.erase(0, text.find("\n\n"));
            const std::size_t from = text.find("\nvec3 " + function + "(");
            if (from != std::string::npos) {
                const std::size_t comment = text.rfind("\n\n", from);
                text.erase(comment, text.find("\n}\n", from) + 3 - comment);
            }
            for (std::size_t at; (at = text.find(function + "(")) != std::string::npos;)
                text.replace(at, function.size(), "OUTPUT");
            if (const std::size_t at = text.find("\nuniform float u_inv_gamma;\n");
                at != std::string::npos)
                text.erase(at, 28);
            return text;
        };
        EXPECT_EQ(body(sample.vertex, "sample_light"), body(pixel.vertex, "to_pixel"));
        EXPECT_EQ(body(sample.fragment, "sample_light"), body(pixel.fragment, "to_pixel"));
        EXPECT_NE(body(sample.fragment, "sample_light").find("frag_color = vec4(OUTPUT("),
                  std::string::npos);

        TemporaryDirectory directory;
        const std::filesystem::path vertex = directory.path() / "program.vert";
        const std::filesystem::path fragment = directory.path() / "program.frag";
        std::ofstream(vertex) << sample.vertex;
        std::ofstream(fragment) << sample.fragment;
        const CommandResult link = run_command(shell_quoted(validator) + " -l " +
                                               shell_quoted(vertex) + " " + shell_quoted(fragment));
        EXPECT_EQ(link.exit_code, 0) << link.output;
        // No character beyond printable ASCII that the pixel program lacks.
        auto others = [](const std::string& text) {
            return std::count_if(text.begin(), text.end(), [](char c) {
                return c != '\n' && (c < 0x20 || c >= 0x7f);  // char is signed: UTF-8 is < 0
            });
        };
        EXPECT_EQ(others(sample.vertex), others(pixel.vertex));
        EXPECT_EQ(others(sample.fragment), others(pixel.fragment));
    }
}
