/* trimvr - latency-compensating VR renderer with trim-region PVS.
 * Dispatches to the subcommands in commands.h. */
#include "commands.h"
#include "log.h"

#include <stdio.h>
#include <string.h>

static const tv_command k_commands[] = {
    {"replay", tv_cmd_replay, "the simulated HMD loop: predicted viewcells, asynchronous PVS, per-frame PSNR log"},
    {"demo", tv_cmd_demo, "the same loop live in a window: stereo mirror view, keyboard/mouse head, HUD"},
    {"pvs", tv_cmd_pvs, "compute the PVS of one viewcell and print its size and statistics"},
    {"eval", tv_cmd_eval, "measure a PVS method against sampled ground truth (the paper's metrics)"},
    {"bench", tv_cmd_bench, "every PVS method on the same scenes, viewcells and deltas: tables and plots"},
    {"render", tv_cmd_render, "render frames of a scene along a head-motion path into PNG files"},
    {"info", tv_cmd_info, "load a scene and print its statistics"},
    {"path", tv_cmd_path, "head-motion paths: import a recorded trace, write the synthetic ones, statistics"},
    {"predict-eval", tv_cmd_predict_eval, "prediction error versus horizon of each predictor on paths"},
};
static const int k_command_count = (int)(sizeof k_commands / sizeof k_commands[0]);

static void usage(FILE* f)
{
    fprintf(f, "usage: trimvr <command> [options]\n\n"
               "trimvr renders a simulated head-mounted display from a potentially visible set\n"
               "computed with the Trim Regions method and compares it with the full scene.\n\n"
               "commands:\n");
    for (int i = 0; i < k_command_count; i++)
        fprintf(f, "  %-12s %s\n", k_commands[i].name, k_commands[i].summary);
    fprintf(f, "\nRun 'trimvr <command> --help' for a command's options.\n"
               "Scenes: a .gltf/.glb file or builtin:city, builtin:interior, builtin:house, builtin:unit.\n");
}

int main(int argc, char** argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return 0;
    }
    for (int i = 0; i < k_command_count; i++)
        if (strcmp(argv[1], k_commands[i].name) == 0) {
            char program[64];
            snprintf(program, sizeof program, "trimvr %s", argv[1]);
            tv_log_set_program(program); /* errors read "trimvr render: error: ..." */
            return k_commands[i].run(argc - 2, argv + 2);
        }
    tv_log(TV_LOG_ERROR, "unknown command '%s' (see trimvr --help)", argv[1]);
    return 2;
}
