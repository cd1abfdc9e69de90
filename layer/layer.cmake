# The 2D granular layer (issue 4): Hertz-Mindlin discs, pluviation, block impact.
add_library(gw_layer_obj OBJECT
  ${CMAKE_CURRENT_LIST_DIR}/layer_model.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_create.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_snapshot.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_clumps.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_clump_check.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_contacts.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sim.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_dem.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_watch.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sample.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sample_check.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sample_h5.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sample_pile.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sample_porosity.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sample_settings.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sample_springs.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_springs.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_make.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_impact.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_settled.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_outcome.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_warnings.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_crowns.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_regions.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_h5.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_vtk.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_sweep_model.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_setup.c
  ${CMAKE_CURRENT_LIST_DIR}/layer_make_study.c)
gw_library_objects(gw_layer_obj)
target_include_directories(gw_layer_obj PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(gw_layer_obj PUBLIC gw_common_obj)
add_library(gw_layer STATIC)
target_link_libraries(gw_layer PUBLIC gw_layer_obj gw_common)
