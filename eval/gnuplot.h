/* gnuplot.h - the plots of `trimvr replay` and `trimvr bench` are gnuplot
 * scripts written next to their CSV files and run in that folder. */
#ifndef TRIMVR_EVAL_GNUPLOT_H
#define TRIMVR_EVAL_GNUPLOT_H

#include <stdio.h>

/* A gnuplot script DIR/NAME, opened for writing with its header comment
 * (`writer`, e.g. "trimvr replay"); NULL (warned) when it cannot be written.
 * tv_gnuplot_finish closes it and runs gnuplot in DIR; a missing or failing
 * gnuplot is a warning ending with `kept`, what is complete without plots. */
FILE* tv_gnuplot_begin(const char* dir, const char* name, const char* writer);
void tv_gnuplot_finish(FILE* f, const char* dir, const char* name, const char* kept);

#endif
