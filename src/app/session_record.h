// A recorded session: the scene it started from and every ClothEvent with the step before
// which it happened, plus the step count and state hash it ended with, so a replay can show
// that it reproduced the session bit for bit. Stored as TOML (weft --record / --replay):
//
//   format = 2
//   steps = 5000                              # steps run in all
//   final_state_hash = "0x8f3a..."            # hash_state of the cloth after them
//   scene = "name = ...\n[cloth]\n..."        # the starting scene, every key
//   [[events]]
//   step = 1200                               # applied before step 1200 (counting from 0)
//   kind = "grab"                             # then the kind's fields, see cloth_event.h
//   ...
//   [[events]]
//   step = 1300
//   kind = "edit"                             # a parameter change, typed (scene_edit.h)
//   edits = [{key = "springs.shear.stiffness", value = 250.0}]
//
// Format 1 (still read) stored a parameter change as kind = "parameters" with a whole scene.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/cloth_event.h"

namespace weft::app {

struct TimedEvent {
    std::uint64_t step = 0;  // the event comes before this step (steps counted from 0)
    ClothEvent event;
};

struct SessionRecord {
    std::string scene_toml;          // the scene the session started from, with its parameters then
    std::vector<TimedEvent> events;  // in order of step
    std::uint64_t steps = 0;         // steps run in all
    std::uint64_t final_state_hash = 0;
};

std::string session_to_toml(const SessionRecord& record);

// Reads a recording; on a malformed one returns nothing and sets `error` to
// "SOURCE:LINE:COL: what" (or "SOURCE: what").
std::optional<SessionRecord> session_from_toml(std::string_view text, const std::string& source,
                                               std::string& error);
// The same from a file; "PATH: cannot read ..." if it cannot be read.
std::optional<SessionRecord> read_session_file(const std::string& path, std::string& error);

}  // namespace weft::app
