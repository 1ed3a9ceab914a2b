// SPDX-License-Identifier: Apache-2.0
// `flarekit studio --script ACTIONS.json`: a list of what a user does, played through the studio
// one action per frame (a drag over several), for tests, documentation screenshots and
// benchmarks. The document's own edits run here; the ones that need the window (a drag by the
// pointer, a screenshot, answering a question) are played by the app through its panels.
//
//   {"actions": [{"action": "open", "path": "samples/sunset.png"},
//                {"action": "drag", "from": [600, 200], "to": [900, 260], "frames": 8},
//                {"action": "set", "element": 2, "key": "size", "value": 0.3},
//                {"action": "hide", "element": 1}, {"action": "undo"},
//                {"action": "save", "path": "mine.json"},
//                {"action": "screenshot", "path": "studio.png"}]}
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "Document.h"

namespace flarekit::studio {

struct Action {
    std::string kind;     //!< "open", "drag", "set", ...
    nlohmann::json args;  //!< the whole object
    std::string where;    //!< "script.json: actions[3]", for messages
};

//! The script's actions, each checked for its kind and fields before the window opens.
Result<std::vector<Action>> loadScript(const std::string& path);

//! The action's `field` as [x, y] image pixels, or the error naming it.
Result<Point> actionPoint(const Action& action, const char* field);
//! The action's optional `frames`: an integer in [1, 100000] (`fallback` when absent).
Result<int> actionFrames(const Action& action, int fallback);

//! What the app plays itself (it needs the pointer, the framebuffer or a question's answer).
bool isWindowAction(const std::string& kind);

//! A document action (open, set, hide, show, solo, select, add, duplicate, remove, move, undo,
//! redo, load, save, export, light, view). Errors name the action ("script.json: actions[3]:
//! ...").
Status runDocumentAction(Document& doc, const Action& action);

//! The reference of every action, for `--help-script` and docs/studio.md.
std::string scriptReference();

}  // namespace flarekit::studio
