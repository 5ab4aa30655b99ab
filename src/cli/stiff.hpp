// `frictionref stiff`: the stiff-spring (penalty friction) model's history.
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "frictionref/stiff_spring.hpp"

namespace frictionref::cli {

// "stiff: kf=10000000 dt=6.289308176100629e-05 dt_auto=true output_dt=0.01 ..."
std::string stiff_metadata(const StiffSpringSimulator& simulator);

// The "note: ..." metadata line warning that the undamped contact does not
// converge with static friction above R (StiffSpringOptions::contact_damping),
// or "" when it does not apply.
std::string stiff_ringing_note(const Model& model, const StiffSpringOptions& options);

// Streams the simulator's samples as the stiff CSV (metadata, "t,x,v", rows);
// `observe`, if set, sees every sample too.
void write_stiff_csv(std::FILE* out, StiffSpringSimulator& simulator, const std::string& command,
                     const std::vector<std::string>& extra_metadata,
                     const std::function<void(const StiffSample&)>& observe = {});

}  // namespace frictionref::cli
