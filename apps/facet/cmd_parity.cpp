// facet parity: render scenes on the GPU (one adapter, or every one) and the
// CPU reference and judge them AOV by AOV (analysis/parity.h,
// docs/parity.md); exits with kCheckFailed when any run does not pass, or
// with the first error of a scene that could not be judged, after the
// reports of every scene.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <exception>
#include <memory>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/parity.h"
#include "analysis/parity_run.h"
#include "analysis/reference_cache.h"
#include "commands.h"
#include "engine/renderer.h"
#include "exit_codes.h"
#include "farm_options.h"
#include "material_options.h"
#include "parity_options.h"
#include "parity_output.h"
#include "scene_options.h"
#include "scene_warnings.h"
#include "scenes/input_file.h"
#include "scenes/light_transport.h"

namespace facet::cli {
namespace {

struct ParityCommandOptions {
  std::vector<std::string> scenes;
  SceneEdits edits;  // on every scene, as facet render takes them
  SceneOverrides sceneOverrides;
  ParityFlags flags;
  std::string adapter;
  int renders = 16;
  bool freshReference = false;
};

// The adapters to judge, each checked before any render: one by name (or
// FACET_ADAPTER, or the default), or every one present for "all".
std::vector<gpu::AdapterInfo> chosenAdapters(const std::string& adapter) {
  const gpu::Instance instance = gpu::Instance::create(gpuInstanceFromEnvironment());
  if (adapter != "all") return {instance.requestAdapter(gpuAdapterFromEnvironment(adapter)).info()};
  std::vector<gpu::AdapterInfo> adapters = instance.enumerateAdapters();
  if (adapters.empty()) throw gpu::Error("--adapter all: no Vulkan adapter found");
  return adapters;
}

nlohmann::json adapterJson(const gpu::AdapterInfo& info) {
  return {{"driver", info.driver},
          {"driverInfo", info.driverInfo},
          {"apiVersion", info.apiVersion},
          {"type", gpu::toString(info.type)}};
}

// What the command line made of the scene beyond its files: every edit and
// override, so that the reference's key (analysis/reference_cache.h)
// changes with any of them.
std::string shapedBy(const SceneEdits& e, const SceneOverrides& o) {
  std::ostringstream text;
  text << std::hexfloat;
  const auto list = [&](const char* name, const auto& values) {
    text << ' ' << name << ' ' << values.size();
    for (const auto& v : values) text << ' ' << v;
  };
  const auto word = [&](const char* name, const std::string& value) {
    text << ' ' << name << ' ' << std::quoted(value);
  };
  const auto optional = [&](const char* name, const auto& value) {
    text << ' ' << name << ' ';
    if (value) text << *value;
  };
  text << "materials " << e.materials.size();
  for (const std::string& m : e.materials) text << ' ' << std::quoted(m);
  text << " sets " << e.sets.size();
  for (const std::string& set : e.sets) text << ' ' << std::quoted(set);
  word("variant", e.variant);
  word("size", o.size);
  list("eye", o.eye);
  list("target", o.target);
  list("up", o.up);
  optional("fov", o.fov);
  word("method", o.method);
  optional("tessLevel", o.tessLevel);
  optional("spp", o.spp);
  optional("bounces", o.bounces);
  optional("diffuseBounces", o.diffuseBounces);
  optional("glossyBounces", o.glossyBounces);
  optional("transmissionBounces", o.transmissionBounces);
  word("subdivision", o.subdivision);
  word("environment", o.environment);
  optional("environmentIntensity", o.environmentIntensity);
  optional("environmentRotation", o.environmentRotation);
  word("ibl", o.ibl);
  optional("iblSamples", o.iblSamples);
  word("occlusion", o.occlusion);
  optional("seed", o.seed);
  word("energyCompensation", o.energyCompensation);
  return text.str();
}

ParityCase judgeScene(const std::string& file, const ParityCommandOptions& o,
                      const analysis::ParityTolerances& tolerances, const std::vector<gpu::AdapterInfo>& adapters,
                      std::vector<std::unique_ptr<Renderer>>& renderers) {
  const scene::InputFileLog inputs;  // the scene's files, its materials', cages', maps'
  scene::Scene scene = loadEditedScene(file, o.edits);
  printWarnings(sceneWarnings(scene), false);
  applySceneOverrides(o.sceneOverrides, scene);
  scene::leaveNothingToChoose(scene);
  const analysis::ReferenceStore store{
      analysis::referenceKey(scene, inputs.files(), shapedBy(o.edits, o.sceneOverrides)), o.freshReference};
  std::vector<analysis::ParityCandidate> candidates;
  for (std::size_t a = 0; a < adapters.size(); ++a)
    candidates.push_back({renderers[a].get(), adapters[a].name, adapterJson(adapters[a])});
  return analysis::judgeParity(file, std::move(scene), candidates, *renderers.front(), o.renders, tolerances,
                               o.sceneOverrides.size.empty() ? file + ": image size" : "--size", store);
}

void runParity(const ParityCommandOptions& o) {
  const analysis::ParityTolerances tolerances = chosenTolerances(o.flags);  // a malformed one before any work
  const std::vector<gpu::AdapterInfo> adapters = chosenAdapters(o.adapter);
  checkParityOutputs(o.flags, o.scenes.size() * adapters.size());
  std::vector<std::unique_ptr<Renderer>> renderers;
  // Adapters are named by their full name: a substring of itself.
  for (const gpu::AdapterInfo& info : adapters) renderers.push_back(std::make_unique<Renderer>(info.name));
  // A scene that errors does not stop the others: the reports hold every
  // scene, and the command then ends with the first error.
  std::vector<ParityCase> cases;
  std::exception_ptr firstError;
  for (const std::string& scene : o.scenes) {
    try {
      cases.push_back(judgeScene(scene, o, tolerances, adapters, renderers));
    } catch (const std::exception& e) {
      if (!firstError) firstError = std::current_exception();
      ParityCase errored;
      errored.scene = scene;
      errored.error = e.what();
      cases.push_back(std::move(errored));
    }
  }
  try {
    reportParity(o.flags, cases, "parity");
  } catch (const CheckFailed&) {
    if (!firstError) throw;
  }
  if (firstError) std::rethrow_exception(firstError);
}

}  // namespace

void addParityCommand(CLI::App& app) {
  auto o = std::make_shared<ParityCommandOptions>();
  auto* c = app.add_subcommand("parity", "Render scenes on the GPU and the CPU reference and judge every AOV");
  c->add_option("scenes", o->scenes, "Scene files (.json, .obj cage or glTF)")->required()->check(CLI::ExistingFile);
  addSceneEditOptions(*c, o->edits);
  addSceneOverrideOptions(*c, o->sceneOverrides);
  addParityFlags(*c, o->flags);
  c->add_option("--adapter", o->adapter,
                "GPU adapter: a substring of its name, or 'all' for every adapter present against one CPU reference "
                "(default: FACET_ADAPTER or the first)");
  c->add_option("--renders", o->renders,
                "Sampled or filtered lighting and paths: renders per backend, seeds apart, for the paired t-test "
                "(1: one render each, judged by tolerance alone)")
      ->check(CLI::Range(1, kMostSeeds))
      ->capture_default_str();
  c->add_flag("--fresh-reference", o->freshReference,
              "Render the CPU reference even where facet's cache folder holds it for the same scene, files, flags "
              "and facet build, and keep the new one");
  c->callback([o] { runParity(*o); });
}

}  // namespace facet::cli
