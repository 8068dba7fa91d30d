/*
 * test_ver_report_doc.c - the document model of `delam report` (report_doc.c): a
 * template's placeholders filled (a missing one shown and counted), its title, caption
 * and paragraphs; a table rendered to Markdown and to HTML with its rows' verdict
 * classes and escaped text.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "io.h"
#include "report_doc.h"

static void test_ver_report_doc_expand(void **state)
{
  (void)state;
  rep_vars v = {0};
  rep_vars_num(&v, "fig6:peak_P", 31.96812);
  rep_vars_set(&v, "w", "%s", "better");
  rep_vars_set(&v, "w", "%s", "NOT better"); /* set again: replaced */
  char *s = rep_expand(&v, "peak {fig6:peak_P}, {w}, {nope} end");
  assert_string_equal(s, "peak 31.97, NOT better, {nope?} end");
  assert_int_equal(v.missing, 1);
  free(s);
  rep_vars_num(&v, "x", 0.0 / 0.0);
  s = rep_expand(&v, "{x}");
  assert_string_equal(s, "n/a");
  free(s);
  rep_vars_free(&v);
}

static void test_ver_report_doc_template(void **state)
{
  (void)state;
  char path[128];
  snprintf(path, sizeof path, "/tmp/test_ver_report_doc.%ld.md", (long)getpid());
  assert_int_equal(ver_io_write_atomic(path, "# Fig. {n}: title\n\ncaption: case {c}\n\nfirst\nline {n}\n\n\nsecond\n"), 0);
  rep_vars v = {0};
  rep_vars_set(&v, "n", "6");
  rep_vars_set(&v, "c", "fig6-h8-ppc1");
  rep_doc d = {0};
  char *title, *caption;
  assert_int_equal(rep_doc_template(&d, &v, path, &title, &caption), 0);
  assert_string_equal(title, "Fig. 6: title");
  assert_string_equal(caption, "case fig6-h8-ppc1");
  assert_int_equal(d.n, 2);
  assert_string_equal(d.b[0].text, "first line 6");
  assert_string_equal(d.b[1].text, "second");
  free(title);
  free(caption);
  rep_doc_free(&d);
  remove(path);
  /* a missing file: -1 and a paragraph that says so */
  assert_int_equal(rep_doc_template(&d, &v, path, NULL, NULL), -1);
  assert_int_equal(d.n, 1);
  assert_non_null(strstr(d.b[0].text, "cannot be read"));
  rep_doc_free(&d);
  rep_vars_free(&v);
}

static void test_ver_report_doc_render(void **state)
{
  (void)state;
  rep_doc d = {0};
  rep_doc_head(&d, 2, "v", "Verdicts");
  static const char *const head[2] = {"case", "verdict"};
  rep_table *t = rep_doc_table(&d, 2, head);
  rep_table_row(t, REP_ROW_PASS, "%s\t%s", "fig6-h8-ppc4", "pass");
  rep_table_row(t, REP_ROW_KNOWN, "%s\t%s", "a<b|c", "known-limit");
  char buf[4096];
  FILE *f = fmemopen(buf, sizeof buf, "w");
  assert_int_equal(rep_doc_markdown(&d, f), 0);
  fclose(f);
  assert_non_null(strstr(buf, "## Verdicts\n"));
  assert_non_null(strstr(buf, "| case | verdict |\n|---|---|\n| fig6-h8-ppc4 | pass |\n| a<b\\|c | known-limit |"));
  f = fmemopen(buf, sizeof buf, "w");
  assert_int_equal(rep_doc_html(&d, f, "t"), 0);
  fclose(f);
  assert_non_null(strstr(buf, "<tr class=\"pass\"><td>fig6-h8-ppc4</td><td>pass</td></tr>"));
  assert_non_null(strstr(buf, "<tr class=\"known\"><td>a&lt;b|c</td>"));
  rep_doc_free(&d);
}

int main(void)
{
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_ver_report_doc_expand),
    cmocka_unit_test(test_ver_report_doc_template),
    cmocka_unit_test(test_ver_report_doc_render),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
