// The pass-by-pass search's data between the check and its child processes: the mask of pixels to
// look at (the ones whose final colours part), and each pass's targets' values at those pixels only
// (with its buffers: per-pixel checks there too, decoded buffers whole),
// in a small binary form of oasis's own (length-prefixed, checked on reading).
#pragma once
#include <string>
#include <vector>

#include "check/check_render.h"

namespace oasis {

// "OASISMASK W H\n" then W*H bytes 0 or 1 (bottom row first, as the views read).
bool writePixelMask(const std::string& path, const std::vector<bool>& where, int width, int height, std::string& error);
bool readPixelMask(const std::string& path, std::vector<bool>& where, int& width, int& height, std::string& error);

// Keeps each target's values and each buffer's per-pixel check at the pixels of `where` only (all
// of them where `where` is empty); decoded buffers are kept whole.
void keepPixels(std::vector<PassSnapshot>& snapshots, const std::vector<bool>& where);

std::string encodeSnapshots(const std::vector<PassSnapshot>& snapshots);
// False with `error` for anything but what encodeSnapshots writes.
bool decodeSnapshots(const std::string& bytes, std::vector<PassSnapshot>& snapshots, std::string& error);

}  // namespace oasis
