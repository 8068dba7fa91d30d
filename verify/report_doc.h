/*
 * report_doc.h - the one document model of `delam report` (prefix rep_): headings,
 * paragraphs, figures and tables, rendered to Markdown (REPORT.md) and HTML
 * (index.html) by the same walk, so the two cannot say different things.
 *
 * Prose lives in template files (reports/text/<figure>.md, e.g. reports/text/fig7d.md), not in C: a template is plain
 * text with {name} placeholders filled from a dictionary of numbers and short words
 * that the report sets from the runs (rep_vars).  A placeholder nobody set shows as
 * {name?} and is counted, so a misspelt name is seen, not hidden.
 */
#ifndef DELAM_REPORT_DOC_H
#define DELAM_REPORT_DOC_H

#include <stdio.h>

/* ---- growing strings ---- */
typedef struct {
  char *s;
  size_t n, cap;
} rep_str;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void rep_str_printf(rep_str *b, const char *fmt, ...);
void rep_str_free(rep_str *b);

/* ---- the dictionary of placeholders ---- */
typedef struct {
  char **key, **val;
  int n, cap;
  int missing;            /* placeholders looked up but never set */
} rep_vars;

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
void rep_vars_set(rep_vars *v, const char *key, const char *fmt, ...);
/* A number with %.4g, or "n/a" if it is not finite. */
void rep_vars_num(rep_vars *v, const char *key, double x);
const char *rep_vars_get(const rep_vars *v, const char *key);
void rep_vars_free(rep_vars *v);
/* text with every {name} replaced (malloc'd). */
char *rep_expand(rep_vars *v, const char *text);

/* ---- the document ---- */
enum { REP_ROW_PLAIN = 0, REP_ROW_PASS, REP_ROW_FAIL, REP_ROW_KNOWN, REP_ROW_HEAD };

typedef struct {
  int ncol, nrow;
  char **cell;            /* cell[r * ncol + c]; row 0 is the header */
  int *cls;               /* REP_ROW_* of each row (the header: REP_ROW_HEAD) */
} rep_table;

enum { REP_B_HEAD, REP_B_PARA, REP_B_FIG, REP_B_TABLE, REP_B_TOC };

typedef struct {
  int kind;
  int level;              /* heading level (1, 2)                          */
  char *text;             /* heading, paragraph, or the figure's caption   */
  char id[48];            /* heading anchor, or figure name (name.png/svg) */
  int failed;             /* figure: gnuplot failed                        */
  rep_table *tab;
} rep_block;

typedef struct {
  rep_block *b;
  int n, cap;
} rep_doc;

void rep_doc_head(rep_doc *d, int level, const char *id, const char *text);
void rep_doc_para(rep_doc *d, const char *text);
/* A table of contents: a link to every level-2 heading of the document. */
void rep_doc_toc(rep_doc *d);
void rep_doc_fig(rep_doc *d, const char *name, const char *caption, int failed);
/* A new table of ncol columns with its header cells (ncol strings); rows follow. */
rep_table *rep_doc_table(rep_doc *d, int ncol, const char *const *head);
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
/* Adds a row: fmt holds the cells separated by '\t'. */
void rep_table_row(rep_table *t, int cls, const char *fmt, ...);
void rep_doc_free(rep_doc *d);

/* A template file as paragraphs (blank lines apart) after expansion; the first line,
 * if it starts with "# ", is the title and goes to *title, a paragraph that starts
 * with "caption: " goes to *caption (both malloc'd, NULL if absent; either pointer may
 * be NULL).  0, or -1 if the file cannot be read (a paragraph saying so is added). */
int rep_doc_template(rep_doc *d, rep_vars *v, const char *path, char **title, char **caption);

/* Renders the document; 0, or -1 on a write error. */
int rep_doc_markdown(const rep_doc *d, FILE *f);
int rep_doc_html(const rep_doc *d, FILE *f, const char *title);

#endif
