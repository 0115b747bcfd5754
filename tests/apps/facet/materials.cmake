# facet render --material and --set: what they change (check_materials.sh)
# and each kind of bad input, named with the flag, or the file and field.
add_test(NAME cli.render_materials
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_materials.sh ${facet} ${CMAKE_SOURCE_DIR} ${work}/materials)
set_tests_properties(cli.render_materials PROPERTIES LABELS cli)

set(library ${CMAKE_SOURCE_DIR}/scenes/examples/materials)
set(cube ${CMAKE_SOURCE_DIR}/scenes/examples/gold_cube.gltf)
file(WRITE ${work}/rough.json "{\"preset\": \"gold\", \"roughness\": 3}\n")
file(WRITE ${work}/loop_a.json "{\"extends\": \"loop_b.json\"}\n")
file(WRITE ${work}/loop_b.json "{\"extends\": \"loop_a.json\", \"roughness\": 0.2}\n")
file(WRITE ${work}/names_missing.json
     "{\"objects\": [{\"mesh\": \"${CMAKE_SOURCE_DIR}/scenes/examples/superball.obj\", \"material\": \"lib/missing.json\"}]}\n")
# Each case: name; expected error; flags after `render MODEL -o OUT --size 8x8 --backend cpu`, MODEL first.
foreach(case
    "material_unknown_object|^facet: error: --material 'lid=gold': no object is called 'lid' \\(the objects: 'cube'\\)\n$|${cube};--material;lid=gold"
    "material_unknown_preset|^facet: error: --material: preset: unknown preset 'golld' \\(expected one of: gold,|${superball};--material;golld"
    "material_missing_file|^facet: error: --material: nowhere.json: no such file: |${superball};--material;nowhere.json"
    "material_bad_field|^facet: error: .*rough.json: roughness: must be in \\[0, 1\\], got 3\n$|${superball};--material;${work}/rough.json"
    "material_cycle|^facet: error: .*loop_b.json: extends: material files extend each other in a cycle: loop_a.json -> loop_b.json -> loop_a.json\n$|${superball};--material;${work}/loop_a.json"
    "material_twice|^facet: error: --material 'gold': a material for every object is given twice\n$|${superball};--material;silver;--material;gold"
    "material_no_name|^facet: error: --material '=gold': expected FILE, PRESET, OBJECT=FILE or OBJECT=PRESET\n$|${superball};--material;=gold"
    "scene_names_missing_material_file|^facet: error: .*names_missing.json: objects\\[0\\].material: no such file: .*lib/missing.json\n$|${work}/names_missing.json"
    "set_without_value|^facet: error: --set 'render.spp': expected PATH=VALUE|${superball};--set;render.spp"
    "set_bad_path|^facet: error: --set 'render..spp=4': the path must be|${superball};--set;render..spp=4"
    "set_breaks_rule|^facet: error: .*teacup.json: render.spp \\(--set render.spp=15\\): samples per pixel must be a square number|${CMAKE_SOURCE_DIR}/scenes/examples/teacup.json;--set;render.spp=15"
    "set_material_field|^facet: error: .*teacup.json: materials.gold.roughness \\(--set materials.gold.roughness=2\\): must be in \\[0, 1\\], got 2\n$|${CMAKE_SOURCE_DIR}/scenes/examples/teacup.json;--set;materials.gold.roughness=2"
    "set_index_out_of_range|^facet: error: --set objects\\[3\\].material=gold: objects has 1 entry \\(indices from 0\\)\n$|${CMAKE_SOURCE_DIR}/scenes/examples/teacup.json;--set;objects[3].material=gold"
    "set_model_material|^facet: error: --set objects\\[0\\].material=gold: a .gltf model takes --set for render, camera and environment fields only|${cube};--set;objects[0].material=gold"
    "set_model_camera|^facet: error: --set: camera.fov: must be in \\[0.001, 179\\], is 200\n$|${cube};--set;camera.fov=200"
    "variant_unknown|^facet: error: .*gold_cube.gltf: extensions.KHR_materials_variants: no material variant is named 'navy' \\(the file declares none\\)\n$|${cube};--variant;navy"
    "variant_not_gltf|^facet: error: .*superball.obj: a material variant is one of a glTF file's \\(KHR_materials_variants\\): variant 'navy' is named, and this is no glTF file\n$|${superball};--variant;navy")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 expect)
  list(SUBLIST parts 2 -1 flags)
  facet_cli_failure(render_${name} 1 "${expect}" ${work}/${name}.png "" ${facet} render ${flags} -o
                    ${work}/${name}.png --size 8x8 --backend cpu)
endforeach()
