// The names and modal groups of G and M codes: which group a code belongs to and why an
// unsupported one is refused (LinuxCNC numbering). Part of Parser.
#include "parser.h"

namespace frezka::gcode {

std::string gName(int code10)
{
    std::string s = "G" + std::to_string(code10 / 10);
    if (code10 % 10)
        s += "." + std::to_string(code10 % 10);
    return s;
}

// The modal group of each G code, and why an unsupported one is refused: one case per code, a
// table as long as the list of G codes, kept whole so that a code is looked up in one place.
int gGroup(int code10, bool *supported, const char **reason)
{
    *supported = true;
    *reason = "";
    auto refuse = [&](int group, const char *why) {
        *supported = false;
        *reason = why;
        return group;
    };
    switch (code10) {
    case 0:
    case 10:
    case 20:
    case 30:
    case 50:
    case 51:
    case 52:
    case 382:
    case 383:
    case 384:
    case 385:
    case 730:
    case 800:
    case 810:
    case 820:
    case 830:
    case 850:
    case 890:
        return kGMotion;
    case 40:
    case 53: // G5.3 ends a NURBS: group 0 in LinuxCNC
    case 100:
    case 280:
    case 281:
    case 300:
    case 301:
    case 530:
    case 920:
    case 921:
    case 922:
    case 923:
        return kGNonModal;
    case 170:
    case 180:
    case 190:
        return kGPlane;
    case 900:
    case 910:
        return kGDistance;
    case 901:
    case 911:
        return kGArcDistance;
    case 930:
    case 940:
        return kGFeedMode;
    case 200:
    case 210:
        return kGUnits;
    case 400:
    case 410:
    case 411:
    case 420:
    case 421:
        return kGCutterComp;
    case 430:
    case 431:
    case 432:
    case 490:
        return kGToolLength;
    case 980:
    case 990:
        return kGRetract;
    case 540:
    case 550:
    case 560:
    case 570:
    case 580:
    case 590:
    case 591:
    case 592:
    case 593:
        return kGCoordSystem;
    case 610:
    case 611:
    case 640:
        return kGPathControl;
    case 970:
        return kGSpindleMode;
    // Known to LinuxCNC, refused by Frezka.
    case 330:
    case 331:
        return refuse(kGMotion, "spindle-synchronized motion");
    case 760:
        return refuse(kGMotion, "threading cycle");
    case 840:
    case 860:
    case 870:
    case 880:
        return refuse(kGMotion, "tapping and boring cycle");
    case 700:
    case 710:
    case 711:
    case 712:
    case 720:
    case 721:
    case 722:
        return refuse(kGMotion, "lathe cycle");
    case 70:
    case 80:
        return refuse(15, "lathe diameter mode");
    case 171:
    case 181:
    case 191:
        return refuse(kGPlane, "UVW plane");
    case 520:
        return refuse(kGNonModal, "local coordinate offset");
    case 950:
        return refuse(kGFeedMode, "feed per revolution");
    case 960:
        return refuse(kGSpindleMode, "constant surface speed");
    default:
        return -1;
    }
}

int mGroup(int code, bool *supported, const char **reason)
{
    *supported = true;
    *reason = "";
    auto refuse = [&](int group, const char *why) {
        *supported = false;
        *reason = why;
        return group;
    };
    switch (code) {
    case 0:
    case 1:
    case 2:
    case 30:
        return kMStop;
    case 6:
    case 61:
        return kMToolChange;
    case 3:
    case 4:
    case 5:
        return kMSpindle;
    case 7:
    case 8:
    case 9:
        return kMCoolant;
    case 60:
        return refuse(kMStop, "pallet change pause");
    case 19:
        return refuse(kMSpindle, "spindle orientation");
    case 48:
    case 49:
    case 50:
    case 51:
    case 52:
    case 53:
        return refuse(9, "override control");
    case 62:
    case 63:
    case 64:
    case 65:
    case 66:
    case 67:
    case 68:
        return refuse(5, "digital/analog I/O");
    case 70:
    case 71:
    case 72:
    case 73:
        return kMState;
    default:
        if (code >= 100 && code <= 199)
            return refuse(10, "user-defined M code");
        return -1;
    }
}

} // namespace frezka::gcode
