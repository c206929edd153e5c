// What the back ends share: the messages' constructors and glslang's process initialisation.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "arbiter/targets/targets.h"

namespace arbiter::targets {

void AddMessage(std::vector<Message>* messages, Message::Severity severity, std::string tool,
                int line, std::string text);

// glslang's info log (lines "ERROR: 0:<line>: <text>", "ERROR: Linking <stage> stage: <text>",
// "WARNING: ...", indented continuation lines) as messages of the tool "glslang"; the summary
// ("2 compilation errors.  No code generated.") and "compilation terminated" are dropped.
void AddGlslangLog(std::string_view log, std::vector<Message>* messages);

// glslang::InitializeProcess, once per process.
void EnsureGlslang();

}  // namespace arbiter::targets
