# facet parity and facet compare as a CI gate (docs/parity.md): verdicts
# that mean what they say, flags that break a rule named, and the JUnit and
# JSON reports parsed. Included from CMakeLists.txt, whose ${facet}, ${work}
# and facet_cli_failure it uses.
set(gold ${CMAKE_SOURCE_DIR}/scenes/examples/gold_cube.gltf)
set(courtyard ${CMAKE_SOURCE_DIR}/scenes/environments/courtyard_256x128.hdr)
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(check_reports ${Python3_EXECUTABLE} -B ${CMAKE_CURRENT_SOURCE_DIR}/check_parity_reports.py)

# The cube scaled by 1e-11 under a camera framed for the unit cube: nothing
# covered, nothing judged, never a pass.
file(WRITE ${work}/vanished_cube.json "{\"camera\": {\"eye\": [2, 1.5, 3], \"target\": [0, 0, 0]}, \"objects\": [{\"mesh\": \"${CMAKE_SOURCE_DIR}/scenes/cages/cube.obj\", \"transform\": {\"scale\": 1e-11}}]}\n")
facet_cli_failure(parity_nothing_covered 5
                  "^facet: error: parity: .*vanished_cube.json: insufficient coverage: 0 pixels covered on both, fewer than the 16 needed to judge \\(--min-coverage\\)\n$"
                  "" "" ${facet} parity ${work}/vanished_cube.json --size 16x12)
facet_cli_failure(parity_under_min_coverage 5 "insufficient coverage: [0-9]+ pixels covered on both, fewer than the 100000"
                  "" "" ${facet} parity ${gold} --size 16x12 --min-coverage 100000)
add_test(NAME cli.parity_junit_insufficient_coverage
         COMMAND ${check_reports} 5 ${work}/vanished.xml "insufficient coverage" ${facet} parity
                 ${work}/vanished_cube.json --size 16x12)
set_tests_properties(cli.parity_nothing_covered cli.parity_under_min_coverage cli.parity_junit_insufficient_coverage
                     PROPERTIES LABELS "cli;gpu")

# Flags that break a rule, named before any render.
foreach(case "depth=abc;depth=abc" "alpha=0,0;alpha=0,0" "beauty=1e-4;beauty=1e-4" "beauty=-1,0;beauty=-1,0"
        "normal=0,inf;normal=0,inf")
  list(GET case 0 value)
  list(GET case 1 shown)
  string(MAKE_C_IDENTIFIER "${value}" stem)
  facet_cli_failure(parity_tolerance_${stem} 1
                    "^facet: error: --tolerance '${shown}': expected AOV=ABS,REL with AOV one of depth, normal, beauty and ABS, REL finite numbers >= 0\n$"
                    "" "" ${facet} parity ${gold} --size 16x12 --tolerance ${value})
endforeach()
# The adapter is checked before the scene is even read.
facet_cli_failure(parity_missing_adapter 3 "^facet: error: no adapter name contains 'no-such-gpu'" "" ""
                  ${facet} parity ${work}/bad_scene.json --adapter no-such-gpu)
facet_cli_failure(parity_heatmap_of_two_runs 1 "^facet: error: --heatmap '.*two.png': draws one run, and there are 2" "" ""
                  ${facet} parity ${gold} ${gold} --size 16x12 --heatmap ${work}/two.png)
facet_cli_failure(parity_heatmap_aov_alone 1 "^facet: error: --heatmap-aov 'beauty': needs --heatmap" "" ""
                  ${facet} parity ${gold} --size 16x12 --heatmap-aov beauty)

# The reports of runs that pass and that fail (the 1e-12 cube of CMakeLists.txt).
add_test(NAME cli.parity_junit_pass
         COMMAND ${check_reports} 0 ${work}/gold.xml none ${facet} parity ${gold} ${gold} --size 16x12
                 --tolerance depth=0,2e-4 --tolerance beauty=1e-4,1e-3)
add_test(NAME cli.parity_junit_fail
         COMMAND ${check_reports} 5 ${work}/micro.xml fail ${facet} parity ${work}/micro_cube.json --size 16x12)
# A scene that does not load is an <error> in the reports, the scenes around
# it are judged, and the command exits with its error.
add_test(NAME cli.parity_junit_error
         COMMAND ${check_reports} 1 ${work}/errored.xml none ${facet} parity ${gold} ${work}/bad_scene.json ${gold}
                 --size 16x12 --tolerance depth=0,2e-4 --tolerance beauty=1e-4,1e-3)
# Sampled lighting: paired renders judged by the t-test.
add_test(NAME cli.parity_sampled_t_test
         COMMAND ${facet} parity ${gold} --size 16x12 --env ${courtyard} --ibl sampled --renders 4
                 --heatmap ${work}/sampled_heat.png --heatmap-aov beauty)
set_tests_properties(cli.parity_sampled_t_test PROPERTIES PASS_REGULAR_EXPRESSION
                     "paired t-test over 4 renders.*parity: within tolerance")
set_tests_properties(cli.parity_junit_pass cli.parity_junit_fail cli.parity_junit_error cli.parity_sampled_t_test
                     PROPERTIES LABELS "cli;gpu")

# facet compare: a stored render against itself passes; the GPU's render
# 1% too bright (FACET_FAULT) fails.
foreach(case "plain;16x12" "small;8x6")
  list(GET case 0 name)
  list(GET case 1 size)
  add_test(NAME cli.compare_render_${name}
           COMMAND ${facet} render ${gold} -o ${work}/golden_${name}.exr --size ${size} --backend cpu --env ${courtyard})
  set_tests_properties(cli.compare_render_${name} PROPERTIES LABELS cli FIXTURES_SETUP golden_images)
endforeach()
add_test(NAME cli.compare_render_biased
         COMMAND ${CMAKE_COMMAND} -E env FACET_FAULT=beauty-bias ${facet} render ${gold} -o ${work}/golden_biased.exr
                 --size 16x12 --env ${courtyard})
set_tests_properties(cli.compare_render_biased PROPERTIES LABELS "cli;gpu" FIXTURES_SETUP biased_golden)
add_test(NAME cli.compare_equal
         COMMAND ${check_reports} 0 ${work}/compare_equal.xml none ${facet} compare ${work}/golden_plain.exr
                 ${work}/golden_plain.exr)
add_test(NAME cli.compare_biased
         COMMAND ${check_reports} 5 ${work}/compare_biased.xml fail ${facet} compare ${work}/golden_plain.exr
                 ${work}/golden_biased.exr)
facet_cli_failure(compare_sizes_differ 6
                  "facet: error: compare: .*golden_small.exr: not comparable with .*golden_plain.exr: size 8x6 against 16x12\n$"
                  "" "" ${facet} compare ${work}/golden_plain.exr ${work}/golden_small.exr)
facet_cli_failure(compare_not_an_exr 1 "^facet: error: .*bad_scene.json: cannot read EXR" "" ""
                  ${facet} compare ${work}/bad_scene.json ${work}/golden_plain.exr)
add_test(NAME cli.compare_render_beauty_only
         COMMAND ${facet} render ${gold} -o ${work}/golden_beauty.exr --size 16x12 --backend cpu --env ${courtyard}
                 --aovs beauty)
set_tests_properties(cli.compare_render_beauty_only PROPERTIES LABELS cli FIXTURES_SETUP golden_images)
facet_cli_failure(compare_without_ids 1 "^facet: error: .*golden_beauty.exr: has no ids layer \\(patchId\\)" "" ""
                  ${facet} compare ${work}/golden_plain.exr ${work}/golden_beauty.exr)
set_tests_properties(cli.compare_equal cli.compare_sizes_differ cli.compare_not_an_exr cli.compare_without_ids
                     PROPERTIES LABELS cli FIXTURES_REQUIRED golden_images)
set_tests_properties(cli.compare_biased PROPERTIES LABELS "cli;gpu" FIXTURES_REQUIRED "golden_images;biased_golden")
# Golden sets of a Monte Carlo estimate: paired by seed and judged by the
# paired t-test, a fault caught, and every set that estimates another
# picture refused as not comparable (exit 6), naming what differs.
add_test(NAME cli.compare_golden_sets COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_golden_sets.sh ${facet}
                                              ${CMAKE_SOURCE_DIR} ${work}/golden_sets)
set_tests_properties(cli.compare_golden_sets PROPERTIES LABELS "cli;gpu")
# The CPU reference kept in the cache folder between runs of one command,
# rendered anew for any change.
add_test(NAME cli.parity_reference_cache COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_reference_cache.sh ${facet}
                                                 ${CMAKE_SOURCE_DIR} ${work}/reference_cache)
set_tests_properties(cli.parity_reference_cache PROPERTIES LABELS "cli;gpu")

# Every adapter present, each against one CPU reference.
add_test(NAME cli.parity_all_adapters
         COMMAND ${check_reports} 0 ${work}/all_adapters.xml none ${facet} parity ${gold} --size 16x12 --adapter all)
set_tests_properties(cli.parity_all_adapters PROPERTIES LABELS "cli;gpu")
