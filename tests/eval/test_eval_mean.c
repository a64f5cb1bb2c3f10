/* test_eval_mean.c - tv_eval_mean (eval/eval_common.h) over viewcells: the
 * overflow share is the overflowing pixels over the active pixels, both
 * summed, although the row's overflow_pixels is a sum and its active_pixels
 * a mean (their ratio overstates the share by the viewcell count). */
#include "eval_common.h"
#include "test.h"

#include <string.h>

static tv_eval_cell cell(uint64_t active, uint64_t overflow)
{
    tv_eval_cell c;
    memset(&c, 0, sizeof c);
    c.st.tr.active_pixels = active;
    c.st.tr.overflow_pixels = overflow;
    return c;
}

static void test_overflow_share(void)
{
    tv_eval_cell c[2] = {cell(1000, 10), cell(3000, 290)};
    tv_eval_cell m = tv_eval_mean(c, 2);
    TV_CHECK(m.st.tr.overflow_pixels == 300 && m.st.tr.active_pixels == 2000);
    TV_CHECK_NEAR(m.overflow_share, 300.0 / 4000.0, 1e-12);
    tv_eval_cell one = tv_eval_mean(c, 1);
    TV_CHECK_NEAR(one.overflow_share, 0.01, 1e-12);
    tv_eval_cell none[1] = {cell(0, 0)};
    TV_CHECK(tv_eval_mean(none, 1).overflow_share == 0.0);
}

/* A pixel out of llvmpipe's loop budget may be resolved wrongly: the bench
 * reports every one of them, so the mean sums them. */
static void test_loop_budget_summed(void)
{
    tv_eval_cell c[3] = {cell(1000, 0), cell(1000, 0), cell(1000, 0)};
    c[0].st.tr.loop_budget_pixels = 2;
    c[2].st.tr.loop_budget_pixels = 5;
    TV_CHECK(tv_eval_mean(c, 3).st.tr.loop_budget_pixels == 7);
}

int main(void)
{
    TV_TEST_RUN(test_overflow_share);
    TV_TEST_RUN(test_loop_budget_summed);
    return tv_test_finish();
}
