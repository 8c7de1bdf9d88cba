#pragma once
// The `fit` and `synth` subcommands of cyclopt-foot (seed 001, chapter 4; issue 20).

namespace cyclopt::client {

// cyclopt-foot fit [options] TRIAL... : the seed's three fit steps on marker files.
int run_fit_command(int argc, char** argv);
// cyclopt-foot synth [options] : synthetic marker trials of a known foot.
int run_synth_command(int argc, char** argv);

}  // namespace cyclopt::client
