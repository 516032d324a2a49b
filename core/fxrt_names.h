/* The host links the renderer once per number type into one program, so
 * with FXRT_MULTI defined every external symbol whose code depends on the
 * number type gets the type's suffix (render_row -> render_row_q16). The
 * Q16.16 scalar library (fx_*) is the same in every build and keeps its
 * names. Firmware builds one number type and leaves the names alone. */
#ifndef FXRT_NAMES_H
#define FXRT_NAMES_H

#ifdef FXRT_MULTI
#if FXRT_NUMBER == FXRT_Q16
#define FXRT_SYM(name) name##_q16
#elif FXRT_NUMBER == FXRT_FLOAT
#define FXRT_SYM(name) name##_float
#else
#define FXRT_SYM(name) name##_double
#endif
#define num_cot_deg FXRT_SYM(num_cot_deg)
#define num_cos_deg FXRT_SYM(num_cos_deg)
#define color_to_rgb8 FXRT_SYM(color_to_rgb8)
#define cam_setup FXRT_SYM(cam_setup)
#define cam_strerror FXRT_SYM(cam_strerror)
#define cam_ray FXRT_SYM(cam_ray)
#define cam_fine FXRT_SYM(cam_fine)
#define geom_plane_make FXRT_SYM(geom_plane_make)
#define geom_sphere_make FXRT_SYM(geom_sphere_make)
#define geom_triangle_make FXRT_SYM(geom_triangle_make)
#define geom_box_make FXRT_SYM(geom_box_make)
#define geom_plane_hit FXRT_SYM(geom_plane_hit)
#define geom_sphere_hit FXRT_SYM(geom_sphere_hit)
#define geom_triangle_hit FXRT_SYM(geom_triangle_hit)
#define geom_box_hit FXRT_SYM(geom_box_hit)
#define world_init FXRT_SYM(world_init)
#define world_mesh_update FXRT_SYM(world_mesh_update)
#define mesh_side FXRT_SYM(mesh_side)
#define mesh_link FXRT_SYM(mesh_link)
#define world_hit FXRT_SYM(world_hit)
#define render_pixel FXRT_SYM(render_pixel)
#define render_row FXRT_SYM(render_row)
#define render_row_reference FXRT_SYM(render_row_reference)
#define render_setup FXRT_SYM(render_setup)
#define render_setup_object FXRT_SYM(render_setup_object)
#define render_depth_make FXRT_SYM(render_depth_make)
#define render_resolve FXRT_SYM(render_resolve)
#define render_resolve_flat FXRT_SYM(render_resolve_flat)
#define render_resolve_box FXRT_SYM(render_resolve_box)
#define render_resolve_sphere FXRT_SYM(render_resolve_sphere)
#define render_row_order FXRT_SYM(render_row_order)
#define render_range_check FXRT_SYM(render_range_check)
#define render_depth_test FXRT_SYM(render_depth_test)
#define render_split_test FXRT_SYM(render_split_test)
#define render_split_edge_test FXRT_SYM(render_split_edge_test)
#define render_span_range FXRT_SYM(render_span_range)
#define raycast_row FXRT_SYM(raycast_row)
#define geom_plane_surface FXRT_SYM(geom_plane_surface)
#define geom_sphere_surface FXRT_SYM(geom_sphere_surface)
#define geom_triangle_surface FXRT_SYM(geom_triangle_surface)
#define geom_box_surface FXRT_SYM(geom_box_surface)
#define geom_box_hit_face FXRT_SYM(geom_box_hit_face)
#define geom_plane_occludes FXRT_SYM(geom_plane_occludes)
#define geom_sphere_occludes FXRT_SYM(geom_sphere_occludes)
#define geom_triangle_occludes FXRT_SYM(geom_triangle_occludes)
#define geom_box_occludes FXRT_SYM(geom_box_occludes)
#define shade_color FXRT_SYM(shade_color)
#define shade_object FXRT_SYM(shade_object)
#define shade_point FXRT_SYM(shade_point)
#define shade_point_k FXRT_SYM(shade_point_k)
#define shade_object_k FXRT_SYM(shade_object_k)
#define shade_consts FXRT_SYM(shade_consts)
#define shade_spot_surely_out FXRT_SYM(shade_spot_surely_out)
#define render_shade_setup FXRT_SYM(render_shade_setup)
#define shadow_blocked FXRT_SYM(shadow_blocked)
#define shadow_cull_setup FXRT_SYM(shadow_cull_setup)
#define world_occluded FXRT_SYM(world_occluded)
#define world_find FXRT_SYM(world_find)
#define world_common FXRT_SYM(world_common)
#define render_shade_row FXRT_SYM(render_shade_row)
#define render_row_vis FXRT_SYM(render_row_vis)
#define render_row_reference_vis FXRT_SYM(render_row_reference_vis)
#define render_sample_row FXRT_SYM(render_sample_row)
#define render_fill_rgb FXRT_SYM(render_fill_rgb)
#define render_row_runs FXRT_SYM(render_row_runs)
#define render_srow_setup FXRT_SYM(render_srow_setup)
#define geom_sphere_exit FXRT_SYM(geom_sphere_exit)
#define geom_box_exit FXRT_SYM(geom_box_exit)
#define trace_bounces FXRT_SYM(trace_bounces)
#endif

#endif
