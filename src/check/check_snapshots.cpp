// The pass-by-pass search's data between processes (check/check_snapshots.h).
#include "check/check_snapshots.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/file_output.h"

namespace oasis {
namespace {

constexpr char kSnapshotsMagic[] = "OASISPASSES2\n";
constexpr uint32_t kMaxCount = 1u << 28;  // more values than any frame of the check's size has

void putCount(std::string& out, uint32_t value) { out.append(reinterpret_cast<const char*>(&value), sizeof(value)); }
void putText(std::string& out, const std::string& text) {
    putCount(out, uint32_t(text.size()));
    out += text;
}

struct Reader {
    const std::string& bytes;
    size_t at = 0;
    bool count(uint32_t& value) {
        if (bytes.size() - at < sizeof(value)) return false;
        std::memcpy(&value, bytes.data() + at, sizeof(value));
        at += sizeof(value);
        return value <= kMaxCount;
    }
    bool text(std::string& value) {
        uint32_t size = 0;
        if (!count(size) || bytes.size() - at < size) return false;
        value.assign(bytes, at, size);
        at += size;
        return true;
    }
    bool namedValues(std::string& name, std::vector<float>& values) {
        uint32_t size = 0;
        if (!text(name) || !count(size) || (bytes.size() - at) / sizeof(float) < size) return false;
        values.resize(size);
        if (size) std::memcpy(values.data(), bytes.data() + at, size_t(size) * sizeof(float));  // data() may be null
        at += size_t(size) * sizeof(float);
        return true;
    }
    // A count, then that many named lists of values (a snapshot's targets or its pixel checks).
    bool namedLists(std::vector<std::pair<std::string, std::vector<float>>>& lists) {
        uint32_t size = 0;
        if (!count(size)) return false;
        for (uint32_t i = 0; i < size; ++i) {
            std::string name;
            std::vector<float> values;
            if (!namedValues(name, values)) return false;
            lists.push_back({name, std::move(values)});
        }
        return true;
    }
};

void putNamedValues(std::string& out, const std::string& name, const std::vector<float>& values) {
    putText(out, name);
    putCount(out, uint32_t(values.size()));
    if (!values.empty()) out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
}

}  // namespace

bool writePixelMask(const std::string& path, const std::vector<bool>& where, int width, int height, std::string& error) {
    std::string bytes = "OASISMASK " + std::to_string(width) + " " + std::to_string(height) + "\n";
    for (bool inside : where) bytes += char(inside ? 1 : 0);
    return writeFileWhole(path, bytes, error);
}

bool readPixelMask(const std::string& path, std::vector<bool>& where, int& width, int& height, std::string& error) {
    std::ifstream file(path, std::ios::binary);
    std::stringstream stream;
    stream << file.rdbuf();
    std::string bytes = stream.str();
    size_t end = bytes.find('\n');
    if (!file || end == std::string::npos || std::sscanf(bytes.c_str(), "OASISMASK %d %d", &width, &height) != 2 ||
        width < 1 || height < 1 || width > 32768 || height > 32768 ||
        bytes.size() - end - 1 != size_t(width) * size_t(height)) {
        error = "not a pixel mask: " + path;
        return false;
    }
    where.assign(size_t(width) * size_t(height), false);
    for (size_t i = 0; i < where.size(); ++i) where[i] = bytes[end + 1 + i] != 0;
    return true;
}

// Keeps the values of the pixels of `where`, `channels` floats a pixel.
void keepPixelsOf(std::vector<float>& values, const std::vector<bool>& where, size_t channels) {
    std::vector<float> kept;
    for (size_t p = 0; p < where.size() && (p + 1) * channels <= values.size(); ++p)
        if (where[p]) kept.insert(kept.end(), values.begin() + long(p * channels), values.begin() + long((p + 1) * channels));
    values = std::move(kept);
}

void keepPixels(std::vector<PassSnapshot>& snapshots, const std::vector<bool>& where) {
    if (where.empty()) return;
    for (PassSnapshot& snapshot : snapshots) {
        for (auto& target : snapshot.targets) keepPixelsOf(target.second, where, 4);
        for (auto& check : snapshot.pixelChecks) keepPixelsOf(check.second, where, 1);
    }
}

std::string encodeSnapshots(const std::vector<PassSnapshot>& snapshots) {
    std::string out = kSnapshotsMagic;
    putCount(out, uint32_t(snapshots.size()));
    for (const PassSnapshot& snapshot : snapshots) {
        putText(out, snapshot.pass);
        putCount(out, uint32_t(snapshot.targets.size()));
        for (const auto& [label, values] : snapshot.targets) putNamedValues(out, label, values);
        putCount(out, uint32_t(snapshot.pixelChecks.size()));
        for (const auto& [label, values] : snapshot.pixelChecks) putNamedValues(out, label, values);
        putCount(out, uint32_t(snapshot.buffers.size()));
        for (const BufferSnapshot& buffer : snapshot.buffers) {
            putCount(out, buffer.stride);
            putCount(out, buffer.unordered ? 1u : 0u);
            putNamedValues(out, buffer.name, buffer.values);
        }
    }
    return out;
}

bool decodeSnapshots(const std::string& bytes, std::vector<PassSnapshot>& snapshots, std::string& error) {
    error = "not the child's pass snapshots";
    if (bytes.compare(0, std::strlen(kSnapshotsMagic), kSnapshotsMagic) != 0) return false;
    Reader in{bytes, std::strlen(kSnapshotsMagic)};
    uint32_t passes = 0;
    if (!in.count(passes)) return false;
    snapshots.clear();
    for (uint32_t k = 0; k < passes; ++k) {
        PassSnapshot snapshot;
        if (!in.text(snapshot.pass) || !in.namedLists(snapshot.targets) || !in.namedLists(snapshot.pixelChecks)) return false;
        uint32_t buffers = 0;
        if (!in.count(buffers)) return false;
        for (uint32_t b = 0; b < buffers; ++b) {
            BufferSnapshot buffer;
            uint32_t unordered = 0;
            if (!in.count(buffer.stride) || !in.count(unordered) || unordered > 1 ||
                !in.namedValues(buffer.name, buffer.values))
                return false;
            buffer.unordered = unordered == 1;
            snapshot.buffers.push_back(std::move(buffer));
        }
        snapshots.push_back(std::move(snapshot));
    }
    if (in.at != bytes.size()) return false;
    error.clear();
    return true;
}

}  // namespace oasis
