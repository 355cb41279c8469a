// SPDX-License-Identifier: MIT
// PLY mesh files (docs/scene-format.md, "Mesh files"), ASCII and binary of
// either byte order, read by a reader of our own: Debian packages no PLY
// library for C++ to read them with.
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/mesh_formats.hpp"
#include "geometry/mesh_text.hpp"
#include "litkit/error.hpp"

namespace litkit::detail {

namespace {

enum class Type { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

struct TypeName {
    std::string_view name;
    Type type;
};
constexpr std::array<TypeName, 16> type_names{{
    {"char", Type::Int8},
    {"int8", Type::Int8},
    {"uchar", Type::Uint8},
    {"uint8", Type::Uint8},
    {"short", Type::Int16},
    {"int16", Type::Int16},
    {"ushort", Type::Uint16},
    {"uint16", Type::Uint16},
    {"int", Type::Int32},
    {"int32", Type::Int32},
    {"uint", Type::Uint32},
    {"uint32", Type::Uint32},
    {"float", Type::Float32},
    {"float32", Type::Float32},
    {"double", Type::Float64},
    {"float64", Type::Float64},
}};

std::size_t size_of(Type type) {
    switch (type) {
        case Type::Int8:
        case Type::Uint8:
            return 1;
        case Type::Int16:
        case Type::Uint16:
            return 2;
        case Type::Int32:
        case Type::Uint32:
        case Type::Float32:
            return 4;
        case Type::Float64:
            return 8;
    }
    return 1;
}
bool is_integer(Type type) { return type != Type::Float32 && type != Type::Float64; }

// What a property is to us: a coordinate, a normal's, the face's corners, or nothing.
enum class Role { None, X, Y, Z, Nx, Ny, Nz, Corners };

struct Property {
    std::string name;
    Type type = Type::Float32;
    bool list = false;
    Type count_type = Type::Uint8;
    Role role = Role::None;
    MeshWord place;
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
    MeshWord place;
};

struct Header {
    enum class Format { Ascii, Little, Big } format = Format::Ascii;
    std::vector<Element> elements;
    std::size_t body = 0;         // offset of the first byte after end_header
    std::uint32_t body_line = 0;  // its line (ASCII)
};

std::string plural(std::uint64_t count, std::string_view word) {
    if (count == 1) return "1 " + std::string(word);
    return std::to_string(count) + " " + (word == "vertex" ? "vertices" : std::string(word) + "s");
}

class Reader {
  public:
    Reader(std::string_view bytes, const std::string& name, std::vector<std::uint32_t>* face_lines)
        : bytes_(bytes), name_(name), face_lines_(face_lines) {}

    Mesh read() {
        read_header();
        assign_roles();
        at_ = header_.body;
        for (const Element& element : header_.elements) read_element(element);
        check_end();
        if (mesh_.triangles.empty()) throw IoError(name_, "the file has no faces", FileLoc{name_});
        if (!has_normals_) {
            mesh_.file_normals.clear();
            for (auto& corners : mesh_.triangle_file_normals)
                corners = {missing_file_normal, missing_file_normal, missing_file_normal};
        }
        return std::move(mesh_);
    }

  private:
    [[noreturn]] void fail(const MeshWord& where, const std::string& reason) const {
        throw IoError(name_, reason, FileLoc{name_, where.line, where.column});
    }
    [[noreturn]] void fail_at_byte(std::size_t offset, const std::string& reason) const {
        throw IoError(name_, reason + at_byte(offset), FileLoc{name_});
    }

    // The header: lines of words up to end_header.
    void read_header() {
        MeshWords words(bytes_);
        const MeshWord magic = words.next_word();
        if (magic.text != "ply" || words.line_has_more())
            fail(magic, "not a PLY file: it does not start with the line 'ply'");
        bool format_seen = false;
        while (true) {
            const MeshWord keyword = words.next_word();
            std::vector<MeshWord> rest;
            while (words.line_has_more()) rest.push_back(words.next_word());
            if (keyword.text.empty()) fail(keyword, "the header has no 'end_header' line");
            if (keyword.text == "comment" || keyword.text == "obj_info") continue;
            if (keyword.text == "end_header") {
                if (!rest.empty()) fail(rest[0], "'end_header' stands alone on its line");
                if (!format_seen) fail(keyword, "the header has no 'format' line");
                // The body starts after the line's end ("\n" or "\r\n").
                std::size_t end = words.offset();
                while (end < bytes_.size() && bytes_[end] != '\n') ++end;
                header_.body = std::min(end + 1, bytes_.size());
                header_.body_line = keyword.line + 1;
                return;
            }
            if (keyword.text == "format") {
                if (rest.size() != 2)
                    fail(keyword,
                         "a format line is 'format ascii 1.0' (or binary_little_endian, "
                         "binary_big_endian)");
                if (rest[0].text == "ascii") {
                    header_.format = Header::Format::Ascii;
                } else if (rest[0].text == "binary_little_endian") {
                    header_.format = Header::Format::Little;
                } else if (rest[0].text == "binary_big_endian") {
                    header_.format = Header::Format::Big;
                } else {
                    fail(rest[0], "unknown format " + quoted_word(rest[0].text) +
                                      " (ascii, binary_little_endian or binary_big_endian)");
                }
                if (rest[1].text != "1.0")
                    fail(rest[1], "PLY version " + quoted_word(rest[1].text) +
                                      " is not 1.0, the one version litkit reads");
                format_seen = true;
            } else if (keyword.text == "element") {
                if (rest.size() != 2) fail(keyword, "an element line is 'element NAME COUNT'");
                Element element{std::string(rest[0].text), 0, {}, rest[0]};
                const auto [end, error] = std::from_chars(
                    rest[1].text.data(), rest[1].text.data() + rest[1].text.size(), element.count);
                if (error != std::errc() || end != rest[1].text.data() + rest[1].text.size())
                    fail(rest[1], "element count " + quoted_word(rest[1].text) +
                                      " is not a whole number of 0 or more");
                header_.elements.push_back(std::move(element));
            } else if (keyword.text == "property") {
                if (header_.elements.empty())
                    fail(keyword, "a property line comes before any element line");
                header_.elements.back().properties.push_back(read_property(keyword, rest));
            } else {
                fail(keyword, "unknown header line " + quoted_word(keyword.text) +
                                  " (format, element, property, comment, obj_info, end_header)");
            }
        }
    }

    Type read_type(const MeshWord& word) const {
        for (const TypeName& entry : type_names)
            if (entry.name == word.text) return entry.type;
        fail(word,
             "unknown property type " + quoted_word(word.text) +
                 " (char, uchar, short, ushort, int, uint, float, double, or int8 … float64)");
    }

    Property read_property(const MeshWord& keyword, const std::vector<MeshWord>& rest) const {
        Property property;
        if (!rest.empty() && rest[0].text == "list") {
            if (rest.size() != 4)
                fail(keyword, "a list property line is 'property list COUNT_TYPE TYPE NAME'");
            property.list = true;
            property.count_type = read_type(rest[1]);
            if (!is_integer(property.count_type))
                fail(rest[1], "a list's count type must be an integer type");
            property.type = read_type(rest[2]);
            property.name = rest[3].text;
            property.place = rest[3];
        } else {
            if (rest.size() != 2) fail(keyword, "a property line is 'property TYPE NAME'");
            property.type = read_type(rest[0]);
            property.name = rest[1].text;
            property.place = rest[1];
        }
        return property;
    }

    void assign_roles() {
        Element* vertex = nullptr;
        for (Element& element : header_.elements) {
            if (element.name == "vertex" && !vertex) {
                vertex = &element;
                vertex_count_ = element.count;
                static constexpr std::array<std::pair<std::string_view, Role>, 6> roles{{
                    {"x", Role::X},
                    {"y", Role::Y},
                    {"z", Role::Z},
                    {"nx", Role::Nx},
                    {"ny", Role::Ny},
                    {"nz", Role::Nz},
                }};
                int found = 0, normals = 0;
                for (Property& property : element.properties) {
                    for (const auto& [name, role] : roles) {
                        if (property.name != name) continue;
                        if (property.list)
                            fail(property.place,
                                 "vertex property " + property.name + " must not be a list");
                        property.role = role;
                        (role == Role::X || role == Role::Y || role == Role::Z ? found : normals)++;
                    }
                }
                if (found != 3)
                    fail(element.place, "the vertex element needs properties x, y and z");
                if (normals != 0 && normals != 3)
                    fail(element.place,
                         "the vertex element has some of nx, ny, nz but not all three");
                has_normals_ = normals == 3;
            } else if (element.name == "face" && !faces_seen_) {
                faces_seen_ = true;
                Property* corners = nullptr;
                for (Property& property : element.properties)
                    if (!corners && property.list &&
                        (property.name == "vertex_indices" || property.name == "vertex_index"))
                        corners = &property;
                if (!corners)
                    fail(element.place,
                         "the face element needs a list property vertex_indices (or vertex_index)");
                if (!is_integer(corners->type))
                    fail(corners->place, "face vertex indices must be of an integer type");
                corners->role = Role::Corners;
            }
        }
        if (!vertex) throw IoError(name_, "the header declares no vertex element", FileLoc{name_});
        if (!faces_seen_)
            throw IoError(name_, "the file has no faces (no face element)", FileLoc{name_});
    }

    // Whatever follows the last element is a sign of a header that does not
    // describe the data.
    void check_end() {
        if (header_.format == Header::Format::Ascii) {
            if (!ascii_) ascii_.emplace(bytes_, header_.body, header_.body_line);
            const MeshWord extra = ascii_->next_word();
            if (!extra.text.empty())
                fail(extra,
                     quoted_word(extra.text) + " follows the last element the header declares");
        } else if (at_ < bytes_.size()) {
            fail_at_byte(at_, plural(bytes_.size() - at_, "byte") +
                                  " follow the last element the header declares");
        }
    }

    // Bytes (binary) or characters (ASCII) each item of `element` takes at least.
    std::uint64_t least_item_size(const Element& element) const {
        std::uint64_t size = 0;
        const bool ascii = header_.format == Header::Format::Ascii;
        for (const Property& property : element.properties)
            size += ascii ? 2 : size_of(property.list ? property.count_type : property.type);
        return std::max<std::uint64_t>(size, 1);
    }

    void read_element(const Element& element) {
        if (!ascii_ && header_.format == Header::Format::Ascii)
            ascii_.emplace(bytes_, header_.body, header_.body_line);
        const std::size_t here = ascii_ ? ascii_->offset() : at_;
        const std::uint64_t room = bytes_.size() - here;
        const std::uint64_t least = least_item_size(element);
        if (element.count > (room + 1) / least)
            fail(element.place, "the header declares " + plural(element.count, element.name) +
                                    " of at least " + plural(least, "byte") + " each, but only " +
                                    plural(room, "byte") + " are left for them");
        if (element.name == "vertex" && element.count == vertex_count_) {
            mesh_.positions.reserve(element.count);
            if (has_normals_) mesh_.file_normals.reserve(element.count);
        }
        for (std::uint64_t item = 0; item < element.count; ++item) {
            glm::vec3 position(0.0f), normal(0.0f);
            for (const Property& property : element.properties) {
                if (property.list) {
                    read_list(element, item, property);
                    continue;
                }
                const Value value = read_value(element, item, property, property.type);
                const int axis = static_cast<int>(property.role) - static_cast<int>(Role::X);
                if (property.role == Role::None) continue;
                if (!std::isfinite(static_cast<float>(value.number)))
                    fail_value(value, element, item,
                               (axis < 3 ? "" : "normal ") + std::string("coordinate ") +
                                   property.name + " is not a finite number");
                (axis < 3 ? position : normal)[axis % 3] = static_cast<float>(value.number);
            }
            if (&element == &header_.elements[vertex_element()]) {
                mesh_.positions.push_back(position);
                if (has_normals_) mesh_.file_normals.push_back(normal);
            }
        }
    }

    std::size_t vertex_element() const {
        for (std::size_t i = 0; i < header_.elements.size(); ++i)
            if (header_.elements[i].name == "vertex") return i;
        return 0;
    }

    struct Value {
        double number = 0;
        MeshWord word;           // ASCII
        std::size_t offset = 0;  // binary
    };

    [[noreturn]] void fail_value(const Value& value, const Element& element, std::uint64_t item,
                                 const std::string& reason) const {
        const std::string what = element.name + " " + std::to_string(item + 1) + ": ";
        if (header_.format == Header::Format::Ascii)
            fail(value.word, what + reason + " (" + quoted_word(value.word.text) + ")");
        fail_at_byte(value.offset, what + reason);
    }

    Value read_value(const Element& element, std::uint64_t item, const Property& property,
                     Type type) {
        Value value;
        if (header_.format == Header::Format::Ascii) {
            if (!ascii_) ascii_.emplace(bytes_, header_.body, header_.body_line);
            value.word = ascii_->next_word();
            if (value.word.text.empty())
                fail(ascii_->here(),
                     "the file ends in " + element.name + " " + std::to_string(item + 1) + " of " +
                         std::to_string(element.count) + ", before its " + property.name);
            std::string problem;
            if (is_integer(type)) {
                long long whole = 0;
                const std::string_view text = value.word.text;
                const auto [end, error] =
                    std::from_chars(text.data(), text.data() + text.size(), whole);
                if (error != std::errc() || end != text.data() + text.size())
                    fail(value.word, element.name + " " + std::to_string(item + 1) + ": " +
                                         property.name + " " + quoted_word(text) +
                                         " is not an integer");
                value.number = static_cast<double>(whole);
            } else if (std::string reason = read_finite(value.word.text, value.number);
                       !reason.empty()) {
                fail(value.word, element.name + " " + std::to_string(item + 1) + ": " +
                                     property.name + " " + quoted_word(value.word.text) + " " +
                                     reason);
            }
            return value;
        }
        value.offset = at_;
        const std::size_t size = size_of(type);
        if (bytes_.size() - at_ < size)
            fail_at_byte(at_, "the file ends in " + element.name + " " + std::to_string(item + 1) +
                                  " of " + std::to_string(element.count) + ", in its " +
                                  property.name);
        const BinaryBytes data{bytes_, header_.format == Header::Format::Big};
        switch (type) {
            case Type::Int8:
                value.number = data.read<std::int8_t>(at_);
                break;
            case Type::Uint8:
                value.number = data.read<std::uint8_t>(at_);
                break;
            case Type::Int16:
                value.number = data.read<std::int16_t>(at_);
                break;
            case Type::Uint16:
                value.number = data.read<std::uint16_t>(at_);
                break;
            case Type::Int32:
                value.number = data.read<std::int32_t>(at_);
                break;
            case Type::Uint32:
                value.number = data.read<std::uint32_t>(at_);
                break;
            case Type::Float32:
                value.number = data.read<float>(at_);
                break;
            case Type::Float64:
                value.number = data.read<double>(at_);
                break;
        }
        at_ += size;
        return value;
    }

    void read_list(const Element& element, std::uint64_t item, const Property& property) {
        const Value count = read_value(element, item, property, property.count_type);
        if (count.number < 0)
            fail_value(count, element, item, property.name + " has a negative length");
        const auto length = static_cast<std::uint64_t>(count.number);
        if (property.role != Role::Corners) {
            for (std::uint64_t i = 0; i < length; ++i)
                read_value(element, item, property, property.type);
            return;
        }
        if (length < 3)
            fail_value(count, element, item,
                       "a face needs 3 or more vertices, this one has " + std::to_string(length));
        corners_.clear();
        for (std::uint64_t i = 0; i < length; ++i) {
            const Value index = read_value(element, item, property, property.type);
            if (index.number < 0 || index.number >= static_cast<double>(vertex_count_))
                fail_value(index, element, item,
                           "vertex index " + std::to_string(static_cast<long long>(index.number)) +
                               " is beyond the file's " + std::to_string(vertex_count_) +
                               " vertices (indices count from 0)");
            corners_.push_back(static_cast<std::uint32_t>(index.number));
        }
        const auto face = static_cast<std::uint32_t>(face_count_++);
        if (face_lines_ && header_.format == Header::Format::Ascii)
            face_lines_->push_back(count.word.line);
        if (mesh_.triangles.size() + (corners_.size() - 2) > max_mesh_file_triangles)
            fail_value(count, element, item,
                       "the file's faces make more than " +
                           std::to_string(max_mesh_file_triangles) + " triangles");
        // docs/spec.md §2: the polygon (v0, v1, …, vk) becomes the fan (v0, vi, vi+1).
        for (std::size_t i = 1; i + 1 < corners_.size(); ++i) {
            mesh_.triangles.push_back({corners_[0], corners_[i], corners_[i + 1]});
            mesh_.triangle_file_normals.push_back({corners_[0], corners_[i], corners_[i + 1]});
            mesh_.triangle_faces.push_back(face);
        }
    }

    std::string_view bytes_;
    const std::string& name_;
    std::vector<std::uint32_t>* face_lines_;
    Header header_;
    std::optional<MeshWords> ascii_;
    std::size_t at_ = 0;  // binary: the next byte
    std::uint64_t vertex_count_ = 0;
    bool has_normals_ = false;
    bool faces_seen_ = false;
    std::uint64_t face_count_ = 0;
    std::vector<std::uint32_t> corners_;
    Mesh mesh_;
};

}  // namespace

Mesh parse_ply(std::string_view bytes, const std::string& name,
               std::vector<std::uint32_t>* face_lines) {
    return Reader(bytes, name, face_lines).read();
}

}  // namespace litkit::detail
