/* commands.h - the trimvr subcommands. Each takes the arguments after its
 * name and returns the process exit status (0 success, 1 failure, 2 usage). */
#ifndef TRIMVR_COMMANDS_H
#define TRIMVR_COMMANDS_H

typedef int (*tv_command_fn)(int argc, char** argv);

typedef struct tv_command {
    const char* name;
    tv_command_fn run;
    const char* summary;
} tv_command;

int tv_cmd_render(int argc, char** argv);
int tv_cmd_info(int argc, char** argv);
int tv_cmd_path(int argc, char** argv);
int tv_cmd_predict_eval(int argc, char** argv);
int tv_cmd_replay(int argc, char** argv);
int tv_cmd_pvs(int argc, char** argv);
int tv_cmd_eval(int argc, char** argv);
int tv_cmd_bench(int argc, char** argv);
int tv_cmd_demo(int argc, char** argv);

#endif
