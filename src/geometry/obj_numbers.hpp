// SPDX-License-Identifier: MIT
// The numbers of an OBJ file checked before tinyobjloader reads them: it
// reads "nan", "abc", "0,5" (a decimal comma) or a missing coordinate as 0
// and says nothing, and only warns about a face index out of range.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace litkit::detail {

// Throws IoError located at "mesh.obj:LINE:COLUMN" for the first coordinate
// of `v`, `vn` or `vt` that is missing, not a number, not finite or beyond a
// float's range, for the first face index that is not an integer or refers
// to no vertex (texture coordinate, normal) of the file, and for what
// tinyobjloader would read with undefined behaviour in the lines litkit does
// not use (the joints and weights of `vw`, the reals of `t` tags).
void check_obj_numbers(std::string_view text, const std::string& name);

// The line of `text` that starts at `at`, split as tinyobjloader splits
// lines (at "\n", "\r" or "\r\n"; an old Mac file's lone "\r" ends a line
// too); `at` moves past its end.
std::string_view next_obj_line(std::string_view text, std::size_t& at);

}  // namespace litkit::detail
