/* trimvr demo in the portable build (TRIMVR_PORTABLE): there is no window
 * system in it, so the command only says so (docs/portable.md). */
#include "commands.h"
#include "log.h"

int tv_cmd_demo(int argc, char** argv)
{
    (void)argc, (void)argv;
    tv_log(TV_LOG_ERROR, "not built in this build (TRIMVR_PORTABLE has no window; use a default build for the demo)");
    return 1;
}
