/// \file
/// The inside of encode_png (src/core/image.cpp) that its tests look at.
#pragma once

#include "litkit/image.hpp"

namespace litkit {

/// The first row encode_png deflates on its second thread, apart from the
/// rows above it: `image.height` (no split) below 512 KiB of filtered rows,
/// else the row where the rows above and below take about the same time
/// to deflate (docs/design.md, "PNG").
int png_split_row(const Image& image);

}  // namespace litkit
