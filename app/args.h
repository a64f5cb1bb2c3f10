/* args.h - table-driven option parsing shared by every trimvr subcommand.
 *
 * Options are `--name value` or `--name=value`; flags take no value. Each
 * option writes into caller-owned storage whose type follows its kind, so a
 * subcommand declares its defaults in a plain struct and one table. Errors are
 * one line naming the command, the option and the bad value. */
#ifndef TRIMVR_ARGS_H
#define TRIMVR_ARGS_H

#include <stdbool.h>

typedef enum tv_arg_kind {
    TV_ARG_STRING, /* const char**        */
    TV_ARG_INT,    /* int*                */
    TV_ARG_FLOAT,  /* float*              */
    TV_ARG_FLAG,   /* bool*, no value     */
    TV_ARG_RES,    /* unsigned[2], "WxH"  */
    TV_ARG_VEC3    /* float[3], "X,Y,Z"   */
} tv_arg_kind;

typedef struct tv_arg {
    const char* name; /* without the leading "--" */
    tv_arg_kind kind;
    void* out;
    const char* metavar; /* shown in --help, NULL for flags */
    const char* help;
} tv_arg;

typedef enum tv_args_result {
    TV_ARGS_OK = 0,
    TV_ARGS_ERROR = 1, /* message already printed */
    TV_ARGS_HELP = 2   /* usage already printed   */
} tv_args_result;

/* Parses argv[0..argc) (argv[0] is the first option, not the command name).
 * Prints usage for --help/-h. `summary` is the one-paragraph description. */
tv_args_result tv_args_parse(const char* command, const char* summary, const tv_arg* args,
                             int arg_count, int argc, char** argv);

void tv_args_usage(const char* command, const char* summary, const tv_arg* args, int arg_count);

#endif
