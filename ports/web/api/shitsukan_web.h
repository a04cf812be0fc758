/* ports/web/api/shitsukan_web.h — the C API of the web explorer (ports/web/README.md).
 *
 * Every function returns the library's StatusCode as an int (0 = ok); sk_status_message()
 * then gives the library's own message. Outputs go to three buffers the caller reads after
 * the call: the RGBA picture (sk_picture_*), floats (sk_floats_*) and a small JSON text
 * (sk_text). The page calls these from a Web Worker through the WASM module's exports
 * (_sk_...); ports/web/native_reference.cpp calls them natively and prints their hashes.
 * One file per paper (api_<paper>.cpp) beside api_common.cpp.
 */
#pragma once
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* api_common.cpp: buffers, status, progress */
const uint8_t* sk_picture_data(void);
int sk_picture_width(void);
int sk_picture_height(void);
const float* sk_floats_data(void);
int sk_floats_count(void);
int sk_floats_columns(void);
const char* sk_text(void);
const char* sk_status_message(void);
const char* sk_status_code_name(void);
float sk_progress(void);
const char* sk_version(void);
void sk_clear_outputs(void);
int sk_init(void);

/* api_okada1987.cpp */
int sk_okada1987_quadtree_level(int R, float beta, unsigned seed, int level, int size);
int sk_okada1987_lattice_level(int R, float beta, unsigned seed, int level, int z_plane, int size);
int sk_okada1987_build(int R, float beta, unsigned seed);
int sk_okada1987_set_stripe(int index, float c, float w, float alpha);
int sk_okada1987_get_stripes(void);
int sk_okada1987_marble_profile(int n);
int sk_okada1987_turbulence_slice(float y, int size, float range);
int sk_okada1987_marble_slice(float k, float y, int size);
int sk_okada1987_wood_slice(float k, float k2, float x0, float y0, float z, int size);
int sk_okada1987_mapping(float k, float y, int size, int forward);
int sk_okada1987_object(int scene, int material, float k, float yaw, float pitch, int size);

/* api_okada1989.cpp */
int sk_okada1989_types(int R, float beta, unsigned seed, int n, int pattern);

/* api_tokai1994.cpp */
int sk_tokai1994_pattern(float D, float d_over_D, float a, float p, unsigned seed);
int sk_tokai1994_step(int step, int size);
int sk_tokai1994_section_load(int which);
int sk_tokai1994_section_points(void);
int sk_tokai1994_section_move(int segment, int index, float r, float z);
int sk_tokai1994_section_curve(int n);
int sk_tokai1994_scale_relief(int size, float height_scale, float lx, float ly, float lz);
int sk_tokai1994_maps(int size);
int sk_tokai1994_patch(float azimuth, float elevation, int size);

/* api_fujimoto2000.cpp */
int sk_fujimoto2000_axis(int kind, int n, int k, int b, int ends);
int sk_fujimoto2000_diagram(int half_axes, double u, int first_label, int window_bases, int width);
int sk_fujimoto2000_follow(double u);
int sk_fujimoto2000_table(int first_label, int max_lines);
int sk_fujimoto2000_ratio(int coordinates);
int sk_fujimoto2000_wr(int figure, int form, float delta, int K, unsigned seed, float jitter, float yaw, float pitch,
                       int size);

/* api_fujimoto2000_terrain.cpp */
int sk_fujimoto2000_terrain(int form, float delta, int K, float jitter_height, float jitter_color, unsigned seed,
                            float yaw, float pitch, int size);

/* api_hirota1998.cpp */
int sk_hirota1998_species(int species);
int sk_hirota1998_run(int species, float sigma, float kappa1, float kappa2, int n_r, int n_h);
int sk_hirota1998_frame(int event, float px_per_cm);

/* api_hirota1998_layers.cpp */
int sk_hirota1998_layers_run(int n_r, int n_h, int cycles, float kappa_h);
int sk_hirota1998_layers_frame(int index, float px_per_cm);
int sk_hirota1998_layers_events(void);
int sk_hirota1998_layers_event(int event, float px_per_cm);

/* api_hirota1998_branch.cpp */
int sk_hirota1998_branch_run(float edge_length, float r_h, float r_n, float kappa, float sigma);
int sk_hirota1998_branch_view(int frame, int view, float yaw, float pitch, int size);

#ifdef __cplusplus
}
#endif
