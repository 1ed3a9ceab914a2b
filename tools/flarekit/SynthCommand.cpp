// SPDX-License-Identifier: Apache-2.0
// flarekit synth: the seeded flare-data generator (flarekit/Synth.h) writing a shard of a set.
#include <cstdio>
#include <memory>

#include "Common.h"
#include "JobOptions.h"
#include "ParamOptions.h"
#include "core/JsonText.h"
#include "flarekit/Synth.h"

namespace flarekit::cli {

namespace {

struct SynthArgs {
    SynthRunOptions run;
    std::string size = "512x512", shard = "0/1", format = "exr", config, backgrounds;
    bool params = false;
    CLI::Option *count = nullptr, *out = nullptr, *seed = nullptr;
};

//! "WxH" and "I/K" as two whole numbers; nothing else.
bool twoNumbers(const std::string& text, char sep, long long& a, long long& b) {
    char tail = 0;
    const std::string pattern = std::string("%lld") + sep + "%lld%c";
    return std::sscanf(text.c_str(), pattern.c_str(), &a, &b, &tail) == 2;
}

Status readArgs(SynthArgs& a) {
    long long w = 0, h = 0, i = 0, k = 0;
    if (!twoNumbers(a.size, 'x', w, h) || w < 1 || h < 1 || w > kMaxSynthSide || h > kMaxSynthSide)
        return invalidInput("--size: expected WxH from 1 to " + std::to_string(kMaxSynthSide) +
                            " pixels a side, got '" + a.size + "'");
    a.run.width = int(w), a.run.height = int(h);
    if (!twoNumbers(a.shard, '/', i, k) || k < 1 || i < 0 || i >= k || k > (1 << 20))
        return invalidInput("--shard: expected I/K with 0 <= I < K (this run's shard of K), got '" +
                            a.shard + "'");
    a.run.shardIndex = int(i), a.run.shardCount = int(k);
    a.run.format = SynthFormat(choiceIndex(kSynthFormatNames, a.format));
    if (!a.config.empty()) {
        auto text = readTextFile(a.config);
        if (!text) return text.error();
        auto config = parseSynthConfig(*text, a.config);
        if (!config) return config.error();
        a.run.config = *config;
    }
    if (!a.backgrounds.empty()) a.run.config.backgrounds = a.backgrounds;
    return Ok{};
}

int runSynth(SynthArgs& a) {
    if (a.params) {
        std::printf("%s", synthParameterReference().c_str());
        return kExitOk;
    }
    for (const CLI::Option* o : {a.count, a.out, a.seed})
        if (o->count() == 0) return report(invalidInput(o->get_name() + " is required"));
    if (Status s = readArgs(a); !s) return report(s.error());
    CliRun run("synth");
    auto result = runSynthJob(a.run, run.events());
    if (!result) return run.finish(Status(result.error()));
    run.finish(Status(Ok{}));
    std::fprintf(stderr, "synth: %llu sample(s) written, %llu already complete%s\n",
                 static_cast<unsigned long long>(result->written),
                 static_cast<unsigned long long>(result->skipped),
                 result->complete ? "; the set is complete (labels.jsonl)" : "");
    return kExitOk;
}

}  // namespace

void addSynthCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<SynthArgs>();
    CLI::App* cmd = app.add_subcommand(
        "synth", "Seeded flare-data generator: samples for training flare-removal networks");
    args->count =
        cmd->add_option("--count", args->run.count, "samples in the whole set (required)");
    cmd->add_option("--size", args->size, "WxH of each sample")->capture_default_str();
    args->out = cmd->add_option("--out", args->run.out, "output folder (required)");
    args->seed = cmd->add_option("--seed", args->run.seed,
                                 "the set's seed (required): sample i of seed S is the same file "
                                 "whatever the shard, thread count or order");
    cmd->add_option("--config", args->config,
                    "synth.json: what the samples are drawn from (docs/synth.md)");
    cmd->add_option("--backgrounds", args->backgrounds,
                    "a folder of background images (default: a procedural sky and ground)");
    cmd->add_option("--shard", args->shard,
                    "I/K: write shard I (0-based) of K, samples [I N/K, (I+1) N/K)")
        ->capture_default_str();
    cmd->add_option("--format", args->format,
                    "flare7kpp (the Flare7K++ training tree), pairs (input/gt/flare/mask PNGs) "
                    "or exr (one multi-channel EXR per sample)")
        ->check(CLI::IsMember(choiceNames(kSynthFormatNames)))
        ->capture_default_str();
    cmd->add_option("--depth", args->run.depth, "pairs: 8 or 16-bit PNGs")
        ->check(CLI::IsMember({8, 16}))
        ->capture_default_str();
    cmd->add_flag("--params", args->params,
                  "print every key of synth.json (Markdown table: default, range, unit)");
    cmd->add_flag("--resume", args->run.resume,
                  "skip the samples already complete in --out (an interrupted run's)");
    cmd->callback([args, &exitCode] { exitCode = runSynth(*args); });
}

}  // namespace flarekit::cli
