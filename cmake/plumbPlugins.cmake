# plumb_add_estimator_plugin(<name> <sources>...): an estimator plugin built outside plumb's tree
# against the installed package. The file is libplumb_estimator_<name>.so, the plugin's one name
# (its info().name must be <name>); only the entry point is exported. Copy it to plumb's lib/ or
# point PLUMB_ESTIMATOR_PATH at its folder, then `plumb plugins` lists it.
function(plumb_add_estimator_plugin name)
  add_library(plumb_estimator_${name} MODULE ${ARGN})
  target_link_libraries(plumb_estimator_${name} PRIVATE plumb::estimator_api)
  target_compile_features(plumb_estimator_${name} PRIVATE cxx_std_20)
  set_target_properties(plumb_estimator_${name} PROPERTIES PREFIX "lib" CXX_VISIBILITY_PRESET hidden
                                                           VISIBILITY_INLINES_HIDDEN ON)
endfunction()
