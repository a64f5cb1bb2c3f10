/* demo_window.h - the demo's GLFW window: Vulkan surface (GLFW_NO_API),
 * held keys and mouse look for the head, key presses as actions, resize and
 * minimise. The only file that includes GLFW. */
#ifndef TRIMVR_APP_DEMO_WINDOW_H
#define TRIMVR_APP_DEMO_WINDOW_H

#include "demo_head.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <vulkan/vulkan.h>

typedef enum tv_action {
    TV_ACTION_NONE = 0,
    TV_ACTION_TOGGLE_PVS,      /* P */
    TV_ACTION_CYCLE_COLOUR,    /* C */
    TV_ACTION_TOGGLE_VIEWCELL, /* V */
    TV_ACTION_TOGGLE_OVERVIEW, /* O */
    TV_ACTION_TOGGLE_FREEZE,   /* F */
    TV_ACTION_SCREENSHOT,      /* F12 */
    TV_ACTION_TOGGLE_HELP,     /* H, F1 */
    TV_ACTION_TOGGLE_HUD,      /* U */
    TV_ACTION_RESET,           /* R */
    TV_ACTION_FOLLOW_PATH,     /* T */
    TV_ACTION_FASTER,          /* + (also keypad) */
    TV_ACTION_SLOWER,          /* - (also keypad) */
    TV_ACTION_QUIT,            /* Esc */
} tv_action;

typedef struct tv_window tv_window;

/* Initialises GLFW and checks for Vulkan presentation support. False with
 * GLFW's own reason in err (no display, no Vulkan loader). */
bool tv_window_system_init(char* err, size_t err_size);
void tv_window_system_shutdown(void);

/* Instance extensions a surface needs (valid until shutdown). */
const char* const* tv_window_instance_extensions(uint32_t* count);

/* A window of width x height pixels. NULL with GLFW's reason in err. */
tv_window* tv_window_open(const char* title, int width, int height, char* err, size_t err_size);
void tv_window_close(tv_window* w);

/* rnd_surface_fn for render/swapchain.h; user is the tv_window. */
VkResult tv_window_create_surface(void* user, VkInstance instance, VkSurfaceKHR* surface);

/* Processes pending events (non-blocking). */
void tv_window_poll(tv_window* w);
bool tv_window_should_close(const tv_window* w);
/* The next queued key action, TV_ACTION_NONE when there is none. */
tv_action tv_window_next_action(tv_window* w);
/* Held movement keys and the mouse travel since the last call while the
 * left button is held (drag to look). */
void tv_window_head_input(tv_window* w, tv_head_input* in);
/* Framebuffer size; zero while minimised. */
void tv_window_framebuffer(tv_window* w, int* width, int* height);
/* Blocks until an event arrives (used while minimised). */
void tv_window_wait(tv_window* w);
void tv_window_set_title(tv_window* w, const char* title);

#endif
