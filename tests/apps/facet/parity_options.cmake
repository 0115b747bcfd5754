# facet parity takes facet render's --material and --set: the edited scene is
# the one judged, and a bad edit is refused with render's error.
set(cube ${CMAKE_SOURCE_DIR}/scenes/examples/gold_cube.gltf)
add_test(NAME cli.parity_material_and_set
         COMMAND ${facet} parity ${cube} --material cube=${CMAKE_SOURCE_DIR}/scenes/examples/materials/white_ceramic.json
                 --set render.spp=4 --size 32x24)
set_tests_properties(cli.parity_material_and_set PROPERTIES LABELS "cli;gpu" PASS_REGULAR_EXPRESSION
                     "settings backend=parity size=32x24 spp=4 .*parity: within tolerance")
file(WRITE ${work}/parity_rough.json "{\"preset\": \"gold\", \"roughness\": 3}\n")
facet_cli_failure(parity_material_unknown_object 1
                  "^facet: error: --material 'lid=gold': no object is called 'lid' \\(the objects: 'cube'\\)\n$" "" ""
                  ${facet} parity ${cube} --material lid=gold --size 8x8)
facet_cli_failure(parity_material_bad_field 1
                  "^facet: error: .*parity_rough.json: roughness: must be in \\[0, 1\\], got 3\n$" "" ""
                  ${facet} parity ${cube} --material ${work}/parity_rough.json --size 8x8)
facet_cli_failure(parity_set_model_material 1
                  "^facet: error: --set objects\\[0\\].material=gold: a .gltf model takes --set for render, camera and environment fields only"
                  "" "" ${facet} parity ${cube} --set objects[0].material=gold --size 8x8)
