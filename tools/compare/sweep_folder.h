// A sweep folder's identity: DIR/sweep_settings.txt names the spec and the settings its
// points were measured with (config, size, runs, warm-up, frames, backend, reference,
// metric, mask). A folder belongs to one spec and its settings: every run, resume, job,
// tune and merge checks it and refuses a folder of another sweep, naming both.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tools/compare/sweep_spec.h"

namespace volgraph::compare {

// The identity of a sweep as DIR/sweep_settings.txt holds it: "key value" lines.
std::string sweep_identity_text(const SweepSpec& spec);
// DIR/sweep_settings.txt's text; nullopt when the folder has none (or an empty one, the
// remains of a failed write, while the folder holds no point). Throws ConfigError when it
// cannot be read, or when the folder holds points but no identity.
std::optional<std::string> read_sweep_identity(const std::string& dir);
// Checks that DIR belongs to `spec` (its identity, as the command applies it); records
// the identity in a folder that has none (written whole: temporary name, then rename).
// Throws ConfigError naming the folder's sweep and this command's where they differ.
void claim_sweep_folder(const SweepSpec& spec, const std::string& dir);
// --merge: the one identity of `dirs` (and `out`, when it holds a sweep already), which
// `spec` (given: the command's SPEC) must match too. Throws ConfigError naming the two
// folders (or the folder and the SPEC) whose sweeps differ, or a folder that is no sweep's.
std::string common_sweep_identity(const std::vector<std::string>& dirs, const std::string& out, const SweepSpec* spec);
// The spec's figures back from an identity (file, config, size, runs, warm-up, frames,
// backend, reference, metric, mask; no points): what a merge without SPEC reports.
SweepSpec spec_of_identity(const std::string& identity);
// "size 32x18 against 16x9, spec a.json against b.json": the lines that differ.
std::string identity_difference(const std::string& held, const std::string& now);

}  // namespace volgraph::compare
