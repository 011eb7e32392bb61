#pragma once
// The file a save writes (docs/grinder.md, "File format"): the controller's data byte for byte
// with the 16-byte header and the system they came from, so a save-then-load round trip
// restores the header. The old tools wrote the bare data (".bin"); such files still open, with
// no header and no system.
//
//   FREZKA-GRINDER 1\n
//   system: k51\n                         anc | k51 | hedit
//   header: 48524944454C2034322020202020\n 16 bytes, 32 hex digits
//   length: 21767\n                       data bytes that follow the blank line
//   \n
//   <data>

#include "driver/grinder/family.h"
#include "driver/grinder/frame.h"

#include <optional>
#include <string>

namespace frezka::grinder {

struct GrinderFile
{
    bool container = false; // false: a bare data file of the old tools
    Family family = Family::K51;
    Header header{};
    Bytes data;
    bool operator==(const GrinderFile &) const = default;
};

// The container's bytes (container is taken as true).
Bytes encodeGrinderFile(const GrinderFile &file);
// A container, or bare data when the bytes do not start with the magic line. A damaged
// container gives nullopt with an English reason in `error`.
std::optional<GrinderFile> decodeGrinderFile(const Bytes &bytes, std::string &error);

} // namespace frezka::grinder
