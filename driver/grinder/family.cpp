#include "driver/grinder/family.h"

#include "driver/grinder/imagecheck.h"

namespace frezka::grinder {

namespace {
const FamilyInfo kFamilies[] = {
    {Family::Anc, "anc", Framing::Anc, Code::AncLoad, Code::AncSave, Code::AncSave,
     kAncImageSizeWithWheel, 4800}, // ANCLOAD/ANCSAVE's rate (the manual's table); 9600 works too
    {Family::K51, "k51", Framing::K51, Code::Load, Code::Request, Code::Save, kK51ImageSize, 9600},
    {Family::HardChrome, "hedit", Framing::K51, Code::LoadHardChrome, Code::RequestHardChrome,
     Code::SaveHardChrome, kHardChromeSize, 9600},
    // The manual lists no request or save for a table: APROXTAB only sent it.
    {Family::Table, "table", Framing::K51, Code::LoadTable, Code::Request, Code::Save, 0, 9600,
     false},
};
} // namespace

const FamilyInfo &familyInfo(Family family)
{
    return kFamilies[static_cast<int>(family)];
}

std::optional<Family> familyFromId(std::string_view id)
{
    for (const FamilyInfo &info : kFamilies) {
        if (id == info.id)
            return info.family;
    }
    return std::nullopt;
}

} // namespace frezka::grinder
