// Every file oasis reads (references, shaders) goes through here, so that no input can abort oasis
// or make it block: the file is opened without blocking, checked to be a regular file of at most a
// stated size, then read; anything else is refused with a message naming the file and why.
#pragma once
#include <cstddef>
#include <string>

namespace oasis {

// Reads the regular file `path` whole into `bytes` if it holds at most `maxBytes` bytes. Refuses,
// with `error` = "cannot read PATH: REASON", a missing or unreadable file, a directory, a FIFO, a
// socket, a device (/dev/zero), and a file larger than `maxBytes` (also one that grows past it
// while it is read). A FIFO is opened with O_NONBLOCK, so the check itself cannot block.
bool readRegularFile(const std::string& path, size_t maxBytes, std::string& bytes, std::string& error);

// An open, checked input: the descriptor of a regular file of at most `maxBytes` bytes, for readers
// that look at a header before they read the rest (readPng). -1 with `error` set as above.
int openRegularFile(const std::string& path, size_t maxBytes, std::string& error);
// Reads up to `count` more bytes from `fd` (fewer only at the end of the file); false with `error`
// on a read error.
bool readUpTo(int fd, size_t count, std::string& bytes, const std::string& path, std::string& error);

}  // namespace oasis
