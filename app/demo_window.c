/* demo_window.c - GLFW window, input and surface. */
#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include "demo_window.h"

#include <GLFW/glfw3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ACTION_QUEUE 32

struct tv_window {
    GLFWwindow* glfw;
    tv_action queue[ACTION_QUEUE];
    int head, count;
    double mouse_x, mouse_y;
    bool dragging;
};

/* GLFW reports failures through a callback; the last one becomes the error
 * line, so "no display" reads as GLFW words it. */
static char g_glfw_error[256];

static void on_glfw_error(int code, const char* text)
{
    snprintf(g_glfw_error, sizeof g_glfw_error, "%s (GLFW error 0x%x)", text, code);
}

bool tv_window_system_init(char* err, size_t err_size)
{
    glfwSetErrorCallback(on_glfw_error);
    g_glfw_error[0] = '\0';
    if (!glfwInit()) {
        snprintf(err, err_size, "cannot open a window: %s", g_glfw_error[0] ? g_glfw_error : "glfwInit failed");
        return false;
    }
    if (!glfwVulkanSupported()) {
        snprintf(err, err_size, "cannot open a window: GLFW finds no Vulkan loader with surface support");
        glfwTerminate();
        return false;
    }
    return true;
}

void tv_window_system_shutdown(void) { glfwTerminate(); }

const char* const* tv_window_instance_extensions(uint32_t* count)
{
    return glfwGetRequiredInstanceExtensions(count);
}

static void push(tv_window* w, tv_action a)
{
    if (w->count < ACTION_QUEUE)
        w->queue[(w->head + w->count++) % ACTION_QUEUE] = a;
}

static tv_action action_of_key(int key)
{
    switch (key) {
    case GLFW_KEY_P: return TV_ACTION_TOGGLE_PVS;
    case GLFW_KEY_C: return TV_ACTION_CYCLE_COLOUR;
    case GLFW_KEY_V: return TV_ACTION_TOGGLE_VIEWCELL;
    case GLFW_KEY_O: return TV_ACTION_TOGGLE_OVERVIEW;
    case GLFW_KEY_F: return TV_ACTION_TOGGLE_FREEZE;
    case GLFW_KEY_F12: return TV_ACTION_SCREENSHOT;
    case GLFW_KEY_H:
    case GLFW_KEY_F1: return TV_ACTION_TOGGLE_HELP;
    case GLFW_KEY_U: return TV_ACTION_TOGGLE_HUD;
    case GLFW_KEY_R: return TV_ACTION_RESET;
    case GLFW_KEY_T: return TV_ACTION_FOLLOW_PATH;
    case GLFW_KEY_EQUAL: /* '+' is shift+'=' on most layouts */
    case GLFW_KEY_KP_ADD: return TV_ACTION_FASTER;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: return TV_ACTION_SLOWER;
    case GLFW_KEY_ESCAPE: return TV_ACTION_QUIT;
    default: return TV_ACTION_NONE;
    }
}

static void on_key(GLFWwindow* glfw, int key, int scancode, int action, int mods)
{
    (void)scancode;
    (void)mods;
    tv_window* w = glfwGetWindowUserPointer(glfw);
    tv_action a = action_of_key(key);
    if (action == GLFW_PRESS && a != TV_ACTION_NONE)
        push(w, a);
}

tv_window* tv_window_open(const char* title, int width, int height, char* err, size_t err_size)
{
    tv_window* w = calloc(1, sizeof *w);
    if (!w) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    g_glfw_error[0] = '\0';
    w->glfw = glfwCreateWindow(width, height, title, NULL, NULL);
    if (!w->glfw) {
        snprintf(err, err_size, "cannot create a window: %s", g_glfw_error[0] ? g_glfw_error : "unknown reason");
        free(w);
        return NULL;
    }
    glfwSetWindowUserPointer(w->glfw, w);
    glfwSetKeyCallback(w->glfw, on_key);
    return w;
}

void tv_window_close(tv_window* w)
{
    if (!w)
        return;
    glfwDestroyWindow(w->glfw);
    free(w);
}

VkResult tv_window_create_surface(void* user, VkInstance instance, VkSurfaceKHR* surface)
{
    tv_window* w = user;
    return glfwCreateWindowSurface(instance, w->glfw, NULL, surface);
}

void tv_window_poll(tv_window* w)
{
    (void)w;
    glfwPollEvents();
}

bool tv_window_should_close(const tv_window* w) { return glfwWindowShouldClose(w->glfw); }

tv_action tv_window_next_action(tv_window* w)
{
    if (w->count == 0)
        return TV_ACTION_NONE;
    tv_action a = w->queue[w->head];
    w->head = (w->head + 1) % ACTION_QUEUE;
    w->count--;
    return a;
}

static bool held(tv_window* w, int key) { return glfwGetKey(w->glfw, key) == GLFW_PRESS; }

void tv_window_head_input(tv_window* w, tv_head_input* in)
{
    memset(in, 0, sizeof *in);
    in->forward = held(w, GLFW_KEY_W) || held(w, GLFW_KEY_UP);
    in->back = held(w, GLFW_KEY_S) || held(w, GLFW_KEY_DOWN);
    in->left = held(w, GLFW_KEY_A) || held(w, GLFW_KEY_LEFT);
    in->right = held(w, GLFW_KEY_D) || held(w, GLFW_KEY_RIGHT);
    in->up = held(w, GLFW_KEY_E) || held(w, GLFW_KEY_SPACE);
    in->down = held(w, GLFW_KEY_Q) || held(w, GLFW_KEY_LEFT_CONTROL);
    in->fast = held(w, GLFW_KEY_LEFT_SHIFT) || held(w, GLFW_KEY_RIGHT_SHIFT);
    double x, y;
    glfwGetCursorPos(w->glfw, &x, &y);
    bool dragging = glfwGetMouseButton(w->glfw, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    if (dragging && w->dragging) {
        in->look_dx = x - w->mouse_x;
        in->look_dy = y - w->mouse_y;
    }
    w->dragging = dragging;
    w->mouse_x = x;
    w->mouse_y = y;
}

void tv_window_framebuffer(tv_window* w, int* width, int* height) { glfwGetFramebufferSize(w->glfw, width, height); }

void tv_window_wait(tv_window* w)
{
    (void)w;
    glfwWaitEvents();
}

void tv_window_set_title(tv_window* w, const char* title) { glfwSetWindowTitle(w->glfw, title); }
