// SPDX-License-Identifier: MIT
// The worked examples of docs/spec.md, read from the page itself and checked
// against the library: each ```text block that starts with "example:" gives
// its inputs above "# results" and the values the equations give below it,
// printed to six significant digits. A change of a number on the page, or of
// an equation in the code, fails here.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/lighting.hpp"
#include "litkit/limits.hpp"
#include "litkit/mesh.hpp"
#include "litkit/scene.hpp"

namespace {

struct Example {
    std::string name;
    std::map<std::string, std::vector<std::string>> inputs;
    std::vector<std::pair<std::string, std::vector<double>>> results;  // in the page's order
};

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

std::vector<Example> read_examples() {
    std::ifstream in(std::string(LITKIT_SOURCE_DIR) + "/docs/spec.md");
    std::vector<Example> examples;
    std::string line;
    bool in_block = false, in_results = false;
    while (std::getline(in, line)) {
        if (!in_block) {
            if (line == "```text") in_block = true;
            continue;
        }
        if (line == "```") {
            in_block = in_results = false;
            continue;
        }
        if (line.rfind("example: ", 0) == 0) {
            examples.push_back({line.substr(9), {}, {}});
            continue;
        }
        if (examples.empty() || !in_block) continue;
        if (line == "# results") {
            in_results = true;
            continue;
        }
        const std::size_t equals = line.find(" = ");
        if (equals == std::string::npos) continue;
        const std::string key = line.substr(0, equals);
        const std::vector<std::string> values = words(line.substr(equals + 3));
        if (!in_results) {
            examples.back().inputs[key] = values;
        } else {
            std::vector<double> numbers;
            for (const std::string& v : values) numbers.push_back(std::stod(v));
            examples.back().results.emplace_back(key, numbers);
        }
    }
    return examples;
}

glm::vec3 vec(const std::vector<std::string>& v) {
    return {std::stof(v.at(0)), std::stof(v.at(1)), std::stof(v.at(2))};
}
float number(const Example& e, const std::string& key, float otherwise) {
    const auto found = e.inputs.find(key);
    return found == e.inputs.end() ? otherwise : std::stof(found->second.at(0));
}

// |value − printed| within the printing's six significant digits.
void expect_printed(double value, double printed, const std::string& what) {
    EXPECT_NEAR(value, printed, 1e-5 * std::max(1.0, std::abs(printed))) << what;
}

}  // namespace

TEST(SpecExamples, EveryWorkedExampleMatchesTheLibrary) {
    const std::vector<Example> examples = read_examples();
    // A broken reader must not pass by finding nothing.
    ASSERT_GE(examples.size(), 13u);
    std::set<std::string> models;
    for (const Example& e : examples) {
        SCOPED_TRACE("docs/spec.md example '" + e.name + "'");
        const auto reflection = litkit::parse_reflection(e.inputs.at("reflection").at(0));
        ASSERT_TRUE(reflection);
        models.insert(e.inputs.at("reflection").at(0));

        litkit::Material material;
        material.color = vec(e.inputs.at("color")) / 255.0f;
        material.ka = number(e, "ka", material.ka);
        material.kd = number(e, "kd", material.kd);
        material.ks = number(e, "ks", material.ks);
        material.shininess = number(e, "shininess", material.shininess);
        litkit::for_each_model_parameter(
            [&](const litkit::ModelParameter& parameter, float& value) {
                value = number(e, std::string(parameter.key), value);
            },
            material);

        const std::string type = e.inputs.at("light").at(0);
        litkit::Light light;
        light.intensity = number(e, "light_intensity", 1.0f);
        litkit::SpotLight spot;
        if (type == "directional") {
            light.kind = litkit::DirectionalLight{vec(e.inputs.at("light_direction"))};
        } else if (type == "point") {
            litkit::PointLight point;
            point.position = vec(e.inputs.at("light_position"));
            if (e.inputs.count("light_attenuation"))
                point.attenuation = vec(e.inputs.at("light_attenuation"));
            light.kind = point;
        } else {
            ASSERT_EQ(type, "spot");
            spot.position = vec(e.inputs.at("light_position"));
            spot.direction = vec(e.inputs.at("light_direction"));
            if (e.inputs.count("light_attenuation"))
                spot.attenuation = vec(e.inputs.at("light_attenuation"));
            spot.cutoff_degrees = number(e, "light_cutoff", spot.cutoff_degrees);
            spot.exponent = number(e, "light_exponent", spot.exponent);
            spot.penumbra = number(e, "light_penumbra", spot.penumbra);
            light.kind = spot;
        }
        const glm::vec3 p = vec(e.inputs.at("point"));
        const glm::vec3 n = vec(e.inputs.at("normal"));
        const glm::vec3 eye = vec(e.inputs.at("eye"));
        const float gamma = number(e, "gamma", 1.0f);

        const litkit::ShadeTerms terms = litkit::shade_terms(
            *reflection, material, std::span<const litkit::Light>(&light, 1), p, n, eye);
        ASSERT_EQ(terms.lights.size(), 1u);
        const litkit::LightTerms& t = terms.lights[0];
        EXPECT_EQ(litkit::shade(*reflection, material, std::span<const litkit::Light>(&light, 1), p,
                                n, eye),
                  terms.total);

        // What each printed name is, computed from the library's values.
        std::map<std::string, std::vector<double>> computed;
        auto put = [&](const std::string& key, const glm::vec3& v) {
            computed[key] = {v.x, v.y, v.z};
        };
        put("V", glm::normalize(eye - p));
        put("L", t.to_light);
        computed["f"] = {t.factor};
        computed["N.L"] = {glm::dot(n, t.to_light)};
        computed["D"] = {t.diffuse};
        computed["S"] = {t.specular};
        put("I", terms.total);
        computed["pixel"] = {double(litkit::to_pixel(terms.total.x, gamma)),
                             double(litkit::to_pixel(terms.total.y, gamma)),
                             double(litkit::to_pixel(terms.total.z, gamma))};
        const glm::vec3 to_eye = glm::normalize(eye - p);
        computed["R.V"] = {glm::dot(2.0f * glm::dot(n, t.to_light) * n - t.to_light, to_eye)};
        computed["N.H"] = {std::max(0.0f, glm::dot(n, glm::normalize(t.to_light + to_eye)))};
        if (type != "directional") {
            const glm::vec3 light_position =
                type == "point" ? std::get<litkit::PointLight>(light.kind).position : spot.position;
            computed["d"] = {glm::length(light_position - p)};
        }
        if (type == "spot") {
            // c = −L·axis; w from the soft edge; s = c^exponent · w.
            const double c = -glm::dot(t.to_light, glm::normalize(spot.direction));
            const double cos_outer = std::cos(glm::radians(double(spot.cutoff_degrees)));
            const double cos_inner =
                std::cos(glm::radians(double(spot.cutoff_degrees) * (1.0 - spot.penumbra)));
            const double u = (c - cos_outer) / (cos_inner - cos_outer);
            const double w = c >= cos_inner ? 1.0 : u * u * (3.0 - 2.0 * u);
            computed["c"] = {c};
            computed["w"] = {w};
            computed["s"] = {(spot.exponent == 0.0f ? 1.0 : std::pow(c, double(spot.exponent))) *
                             w};
        }
        for (const auto& [name, value] : t.intermediates) computed[name] = {value};
        // Gooch's tones as vectors.
        if (computed.count("cool.r")) {
            computed["cool"] = {computed["cool.r"][0], computed["cool.g"][0],
                                computed["cool.b"][0]};
            computed["warm"] = {computed["warm.r"][0], computed["warm.g"][0],
                                computed["warm.b"][0]};
        }

        ASSERT_FALSE(e.results.empty());
        for (const auto& [name, printed] : e.results) {
            const auto found = computed.find(name);
            ASSERT_NE(found, computed.end()) << "the test knows no value named " << name;
            ASSERT_EQ(found->second.size(), printed.size()) << name;
            for (std::size_t i = 0; i < printed.size(); ++i) {
                if (name == "pixel")
                    EXPECT_EQ(found->second[i], printed[i]) << name << "[" << i << "]";
                else
                    expect_printed(found->second[i], printed[i],
                                   name + "[" + std::to_string(i) + "]");
            }
        }
        // Every example states at least the light, the terms and the result.
        for (const char* required : {"L", "f", "D", "S", "I", "pixel"}) {
            bool present = false;
            for (const auto& result : e.results) present = present || result.first == required;
            EXPECT_TRUE(present) << required;
        }
    }
    for (const litkit::ReflectionModel& model : litkit::reflection_models())
        EXPECT_TRUE(models.count(std::string(model.name))) << "no worked example of " << model.name;
}

// The docs' tables of choices and limits against the library's one list of
// each (lighting.hpp, mesh.hpp, limits.hpp): a name added to the library and
// not to docs/scene-format.md's tables or docs/user-guide.md's options, or
// the other way round, fails here.
namespace {

std::string read_doc(const std::string& name) {
    std::ifstream in(std::string(LITKIT_SOURCE_DIR) + "/docs/" + name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The line of docs/`page` that starts with `start` (the one table row).
std::string table_row(const std::string& start, const std::string& page = "scene-format.md") {
    std::istringstream in(read_doc(page));
    std::string found;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(start, 0) != 0) continue;
        EXPECT_TRUE(found.empty()) << "two rows start with " << start;
        found = line;
    }
    EXPECT_FALSE(found.empty()) << "no row of docs/" << page << " starts with " << start;
    return found;
}

// The "quoted" names in column `column` (0: the key) of a table row, in order.
std::vector<std::string> quoted_names(const std::string& whole_row, int column) {
    std::size_t begin = 1;  // after the row's first '|'
    for (int skipped = 0; skipped < column; ++skipped) begin = whole_row.find('|', begin) + 1;
    const std::string row = whole_row.substr(begin, whole_row.find('|', begin) - begin);
    std::vector<std::string> names;
    for (std::size_t at = row.find("`\""); at != std::string::npos; at = row.find("`\"", at)) {
        const std::size_t end = row.find("\"`", at + 2);
        if (end == std::string::npos) break;
        names.push_back(row.substr(at + 2, end - at - 2));
        at = end + 2;
    }
    return names;
}

// The `code` names of a row of docs/user-guide.md's options table, before
// the first ';' (after it come the scene keys the option replaces).
std::vector<std::string> option_values(const std::string& option) {
    const std::string row = table_row("| `" + option + "` |", "user-guide.md");
    const std::size_t begin = row.find('|', 2) + 1;
    const std::string values = row.substr(begin, row.find(';', begin) - begin);
    std::vector<std::string> names;
    for (std::size_t at = values.find('`'); at != std::string::npos; at = values.find('`', at)) {
        const std::size_t end = values.find('`', at + 1);
        if (end == std::string::npos) break;
        names.push_back(values.substr(at + 1, end - at - 1));
        at = end + 1;
    }
    return names;
}

template <class Names>
std::vector<std::string> strings(const Names& names) {
    std::vector<std::string> out;
    for (const auto& name : names) out.emplace_back(name);
    return out;
}

}  // namespace

TEST(DocsTables, ReflectionModelsAreTheLibrarysList) {
    std::vector<std::string> library;
    for (const litkit::ReflectionModel& model : litkit::reflection_models())
        library.emplace_back(model.name);
    // [lighting]'s rows: key, type, allowed, meaning.
    EXPECT_EQ(quoted_names(table_row("| `reflection` | choice | `\""), 2), library);
    EXPECT_EQ(option_values("--reflection M"), library);
}

TEST(DocsTables, ShadingModelsAreTheLibrarysList) {
    EXPECT_EQ(quoted_names(table_row("| `shading` | choice | `\""), 2),
              strings(litkit::shading_names));
    EXPECT_EQ(option_values("--shading S"), strings(litkit::shading_names));
}

TEST(DocsTables, NormalsWeightingsAreTheLibrarysList) {
    EXPECT_EQ(quoted_names(table_row("| `normals` | choice, default"), 2),
              strings(litkit::normals_names));
    EXPECT_EQ(option_values("--normals N"), strings(litkit::normals_names));
}

TEST(DocsTables, LightTypesAreTheLibrarysList) {
    // [[lights]]' rows: key, type, default, allowed, meaning.
    EXPECT_EQ(quoted_names(table_row("| `type` | choice | **required** | `\"ambient\""), 3),
              strings(litkit::light_kind_names));
}

TEST(DocsTables, EveryImageSizeRangeIsTheLibrarysLimit) {
    const std::string range = "1–" + std::to_string(litkit::max_image_side);
    EXPECT_NE(table_row("| `width` | integer |").find(range), std::string::npos);
    EXPECT_NE(table_row("| `height` | integer |").find(range), std::string::npos);
    // Any "1–N" of five digits or more in the pages users read is an image side.
    for (const char* name :
         {"scene-format.md", "spec.md", "user-guide.md", "python.md", "cpp-api.md", "design.md"}) {
        const std::string text = read_doc(name);
        for (std::size_t at = text.find("1–"); at != std::string::npos;
             at = text.find("1–", at + 1)) {
            const std::size_t first = at + std::string("1–").size();
            std::size_t digits = 0;
            while (first + digits < text.size() &&
                   std::isdigit(static_cast<unsigned char>(text[first + digits])))
                ++digits;
            if (digits >= 5) {
                EXPECT_EQ(text.substr(at, first - at + digits), range) << "in docs/" << name;
            }
        }
    }
}

TEST(DocsTables, MaxDepthsRangeAndDefaultAreTheLibrarys) {
    // docs/spec.md §10.1: [lighting] max_depth, and --max-depth.
    const std::string range =
        std::to_string(litkit::min_max_depth) + "–" + std::to_string(litkit::max_max_depth);
    const std::string row = table_row("| `max_depth` | integer, default `" +
                                      std::to_string(litkit::default_max_depth) + "` |");
    EXPECT_NE(row.find("| " + range + " |"), std::string::npos) << row;
    const std::string option = table_row("| `--max-depth N` |", "user-guide.md");
    EXPECT_NE(option.find(range), std::string::npos) << option;
    const std::string spec = table_row("| `[lighting]` | `max_depth` |", "spec.md");
    EXPECT_NE(spec.find("integer " + range + " | " + std::to_string(litkit::default_max_depth)),
              std::string::npos)
        << spec;
}

// The lists of choices written out in running text: the starting file that
// `litkit init` writes and the playground opens with, the scene comments and
// the error messages quoted in README.md and docs/, against the library's
// lists. A model added to the family and missing from any of them fails here.
namespace {

std::vector<std::string> reflection_names() {
    std::vector<std::string> names;
    for (const litkit::ReflectionModel& model : litkit::reflection_models())
        names.emplace_back(model.name);
    return names;
}

std::string trimmed(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" #");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(' ') - first + 1);
}

// The names of the "a | b | c" list that begins at column `at` of lines[i],
// continued on the next lines while a line ends, or the next one starts
// (after "#" and spaces), with '|'.
std::vector<std::string> piped_names(const std::vector<std::string>& lines, std::size_t i,
                                     std::size_t at) {
    std::string list = lines[i].substr(at);
    while (i + 1 < lines.size() &&
           (trimmed(list).ends_with('|') || trimmed(lines[i + 1]).starts_with('|')))
        list.append(" ").append(trimmed(lines[++i]));
    std::vector<std::string> names;
    std::istringstream in(list);
    for (std::string name; std::getline(in, name, '|');)
        if (!trimmed(name).empty()) names.push_back(trimmed(name));
    return names;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

TEST(TextsFollowTheFamily, TheStartingFileListsEveryModelWeightingAndLight) {
    const std::vector<std::string> lines = lines_of(std::string(litkit::default_scene_toml()));
    std::map<std::string, std::vector<std::string>> lists;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        for (const char* label : {"reflection:", "shading:", "normals:"}) {
            const std::string start = std::string("#   ") + label;
            if (lines[i].starts_with(start)) lists[label] = piped_names(lines, i, start.size());
        }
    }
    EXPECT_EQ(lists["reflection:"], reflection_names());
    EXPECT_EQ(lists["shading:"], strings(litkit::shading_names));
    EXPECT_EQ(lists["normals:"], strings(litkit::normals_names));
    for (const std::string& line : lines) {  // the comments fit an 80-column editor
        if (line.starts_with('#')) {
            EXPECT_LT(line.size(), 80u) << line;
        }
    }
    // Every light type is named: the scene's own and the "other" ones.
    const std::string text(litkit::default_scene_toml());
    for (std::string_view kind : litkit::light_kind_names)
        EXPECT_NE(text.find(std::string(kind)), std::string::npos) << kind;
}

TEST(TextsFollowTheFamily, TheDocsListsInCommentsAndMessagesAreTheLibrarys) {
    std::vector<std::string> pages = {std::string(LITKIT_SOURCE_DIR) + "/README.md"};
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(LITKIT_SOURCE_DIR) + "/docs"))
        if (entry.path().extension() == ".md") pages.push_back(entry.path().string());
    int reflection_lists = 0, shading_lists = 0, messages = 0;
    for (const std::string& page : pages) {
        std::ifstream in(page);
        std::stringstream text;
        text << in.rdbuf();
        const std::vector<std::string> lines = lines_of(text.str());
        for (std::size_t i = 0; i < lines.size(); ++i) {
            // A scene file's comment: `reflection = "phong"  # lambert | ...`.
            if (const std::size_t at = lines[i].find("# lambert |"); at != std::string::npos) {
                EXPECT_EQ(piped_names(lines, i, at + 2), reflection_names())
                    << page << ":" << i + 1;
                ++reflection_lists;
            }
            if (const std::size_t at = lines[i].find("# flat |"); at != std::string::npos) {
                EXPECT_EQ(piped_names(lines, i, at + 2), strings(litkit::shading_names))
                    << page << ":" << i + 1;
                ++shading_lists;
            }
            // The reader's message, as the docs quote it: "(one of a, b, c)".
            const std::string one_of = "is not a reflection model (one of ";
            if (const std::size_t at = lines[i].find(one_of); at != std::string::npos) {
                const std::size_t begin = at + one_of.size();
                std::istringstream list(lines[i].substr(begin, lines[i].find(')', begin) - begin));
                std::vector<std::string> names;
                for (std::string name; std::getline(list, name, ',');)
                    names.push_back(trimmed(name));
                EXPECT_EQ(names, reflection_names()) << page << ":" << i + 1;
                ++messages;
            }
        }
    }
    // The README's and docs/scene-format.md's example scenes, the messages
    // quoted in docs/user-guide.md and docs/scene-format.md: found, not skipped.
    EXPECT_GE(reflection_lists, 2);
    EXPECT_GE(shading_lists, 2);
    EXPECT_GE(messages, 2);
}
