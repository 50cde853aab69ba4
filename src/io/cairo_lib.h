/* cairo (and fontconfig, which it loads) opened on the first picture
 * (core/shared_lib.h says why). Included by io/figure.c only: each name
 * below, used as a call, goes through the slot shared_lib_load filled.
 * cairo_lib_load() must succeed before the first call. */
#ifndef NSPD_IO_CAIRO_LIB_H
#define NSPD_IO_CAIRO_LIB_H

#include <cairo-svg.h>
#include <cairo.h>
#include <fontconfig/fontconfig.h>

/* every function io/figure.c calls */
#define CAIRO_LIB_FUNCTIONS(X)                                                                     \
    X(cairo_arc)                                                                                   \
    X(cairo_clip)                                                                                  \
    X(cairo_create)                                                                                \
    X(cairo_debug_reset_static_data)                                                               \
    X(cairo_destroy)                                                                               \
    X(cairo_fill)                                                                                  \
    X(cairo_font_extents)                                                                          \
    X(cairo_font_options_create)                                                                   \
    X(cairo_font_options_destroy)                                                                  \
    X(cairo_font_options_set_antialias)                                                            \
    X(cairo_font_options_set_hint_metrics)                                                         \
    X(cairo_font_options_set_hint_style)                                                           \
    X(cairo_get_source)                                                                            \
    X(cairo_image_surface_create)                                                                  \
    X(cairo_image_surface_create_for_data)                                                         \
    X(cairo_image_surface_get_data)                                                                \
    X(cairo_image_surface_get_height)                                                              \
    X(cairo_image_surface_get_stride)                                                              \
    X(cairo_image_surface_get_width)                                                               \
    X(cairo_line_to)                                                                               \
    X(cairo_move_to)                                                                               \
    X(cairo_paint)                                                                                 \
    X(cairo_pattern_set_filter)                                                                    \
    X(cairo_rectangle)                                                                             \
    X(cairo_restore)                                                                               \
    X(cairo_rotate)                                                                                \
    X(cairo_save)                                                                                  \
    X(cairo_scale)                                                                                 \
    X(cairo_select_font_face)                                                                      \
    X(cairo_set_font_options)                                                                      \
    X(cairo_set_font_size)                                                                         \
    X(cairo_set_line_join)                                                                         \
    X(cairo_set_line_width)                                                                        \
    X(cairo_set_source_rgb)                                                                        \
    X(cairo_set_source_surface)                                                                    \
    X(cairo_show_text)                                                                             \
    X(cairo_status)                                                                                \
    X(cairo_status_to_string)                                                                      \
    X(cairo_stroke)                                                                                \
    X(cairo_surface_destroy)                                                                       \
    X(cairo_surface_finish)                                                                        \
    X(cairo_surface_flush)                                                                         \
    X(cairo_surface_status)                                                                        \
    X(cairo_svg_surface_create_for_stream)                                                         \
    X(cairo_text_extents)                                                                          \
    X(cairo_translate)                                                                             \
    X(FcFini)

enum {
#define CAIRO_LIB_INDEX(f) CAIRO_LIB_##f,
    CAIRO_LIB_FUNCTIONS(CAIRO_LIB_INDEX) CAIRO_LIB_COUNT
#undef CAIRO_LIB_INDEX
};

extern void *cairo_lib_slots[CAIRO_LIB_COUNT];

/* Opens cairo on the first call; NSPD_ERR_IO (with what is missing) if it cannot. */
int cairo_lib_load(void);

/* f's slot as a pointer to f's own type (f, inside its own macro, names
 * the declared function) */
#define CAIRO_LIB_CALL(f)                   ((__typeof__(f) *)cairo_lib_slots[CAIRO_LIB_##f])
#define cairo_arc                           CAIRO_LIB_CALL(cairo_arc)
#define cairo_clip                          CAIRO_LIB_CALL(cairo_clip)
#define cairo_create                        CAIRO_LIB_CALL(cairo_create)
#define cairo_debug_reset_static_data       CAIRO_LIB_CALL(cairo_debug_reset_static_data)
#define cairo_destroy                       CAIRO_LIB_CALL(cairo_destroy)
#define cairo_fill                          CAIRO_LIB_CALL(cairo_fill)
#define cairo_font_extents                  CAIRO_LIB_CALL(cairo_font_extents)
#define cairo_font_options_create           CAIRO_LIB_CALL(cairo_font_options_create)
#define cairo_font_options_destroy          CAIRO_LIB_CALL(cairo_font_options_destroy)
#define cairo_font_options_set_antialias    CAIRO_LIB_CALL(cairo_font_options_set_antialias)
#define cairo_font_options_set_hint_metrics CAIRO_LIB_CALL(cairo_font_options_set_hint_metrics)
#define cairo_font_options_set_hint_style   CAIRO_LIB_CALL(cairo_font_options_set_hint_style)
#define cairo_get_source                    CAIRO_LIB_CALL(cairo_get_source)
#define cairo_image_surface_create          CAIRO_LIB_CALL(cairo_image_surface_create)
#define cairo_image_surface_create_for_data CAIRO_LIB_CALL(cairo_image_surface_create_for_data)
#define cairo_image_surface_get_data        CAIRO_LIB_CALL(cairo_image_surface_get_data)
#define cairo_image_surface_get_height      CAIRO_LIB_CALL(cairo_image_surface_get_height)
#define cairo_image_surface_get_stride      CAIRO_LIB_CALL(cairo_image_surface_get_stride)
#define cairo_image_surface_get_width       CAIRO_LIB_CALL(cairo_image_surface_get_width)
#define cairo_line_to                       CAIRO_LIB_CALL(cairo_line_to)
#define cairo_move_to                       CAIRO_LIB_CALL(cairo_move_to)
#define cairo_paint                         CAIRO_LIB_CALL(cairo_paint)
#define cairo_pattern_set_filter            CAIRO_LIB_CALL(cairo_pattern_set_filter)
#define cairo_rectangle                     CAIRO_LIB_CALL(cairo_rectangle)
#define cairo_restore                       CAIRO_LIB_CALL(cairo_restore)
#define cairo_rotate                        CAIRO_LIB_CALL(cairo_rotate)
#define cairo_save                          CAIRO_LIB_CALL(cairo_save)
#define cairo_scale                         CAIRO_LIB_CALL(cairo_scale)
#define cairo_select_font_face              CAIRO_LIB_CALL(cairo_select_font_face)
#define cairo_set_font_options              CAIRO_LIB_CALL(cairo_set_font_options)
#define cairo_set_font_size                 CAIRO_LIB_CALL(cairo_set_font_size)
#define cairo_set_line_join                 CAIRO_LIB_CALL(cairo_set_line_join)
#define cairo_set_line_width                CAIRO_LIB_CALL(cairo_set_line_width)
#define cairo_set_source_rgb                CAIRO_LIB_CALL(cairo_set_source_rgb)
#define cairo_set_source_surface            CAIRO_LIB_CALL(cairo_set_source_surface)
#define cairo_show_text                     CAIRO_LIB_CALL(cairo_show_text)
#define cairo_status                        CAIRO_LIB_CALL(cairo_status)
#define cairo_status_to_string              CAIRO_LIB_CALL(cairo_status_to_string)
#define cairo_stroke                        CAIRO_LIB_CALL(cairo_stroke)
#define cairo_surface_destroy               CAIRO_LIB_CALL(cairo_surface_destroy)
#define cairo_surface_finish                CAIRO_LIB_CALL(cairo_surface_finish)
#define cairo_surface_flush                 CAIRO_LIB_CALL(cairo_surface_flush)
#define cairo_surface_status                CAIRO_LIB_CALL(cairo_surface_status)
#define cairo_svg_surface_create_for_stream CAIRO_LIB_CALL(cairo_svg_surface_create_for_stream)
#define cairo_text_extents                  CAIRO_LIB_CALL(cairo_text_extents)
#define cairo_translate                     CAIRO_LIB_CALL(cairo_translate)
#define FcFini                              CAIRO_LIB_CALL(FcFini)

#endif
