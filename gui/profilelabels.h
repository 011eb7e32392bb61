#pragma once
// Translatable captions for the keys and choice names of the machine profile
// (machine/configschema.h) and for the machine module's configuration error codes.

#include "machine/machineconfig.h"

#include <QString>

namespace frezka::gui {

// Caption of a profile key ("stepsPerMm" -> "Steps per mm"); the key itself if unknown.
QString profileKeyLabel(const QString &key);
// Caption of a choice value ("airBlow" -> "Air blow").
QString profileChoiceLabel(const QString &name);
// One sentence for a configuration error, in the user's language, naming the key's caption.
QString configErrorText(const machine::ConfigError &error);

} // namespace frezka::gui
