/*
 * report_doc.c - the document model of `delam report` and its two renderings
 * (report_doc.h).
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io.h"
#include "report_doc.h"

void rep_str_printf(rep_str *b, const char *fmt, ...)
{
  va_list ap, aq;
  va_start(ap, fmt);
  va_copy(aq, ap);
  const int k = vsnprintf(NULL, 0, fmt, aq);
  va_end(aq);
  if (k >= 0 && b->n + (size_t)k + 1 > b->cap) {
    size_t cap = b->cap ? b->cap : 256;
    while (b->n + (size_t)k + 1 > cap)
      cap *= 2;
    char *ns = realloc(b->s, cap);
    if (ns) {
      b->s = ns;
      b->cap = cap;
    }
  }
  if (k >= 0 && b->n + (size_t)k + 1 <= b->cap) {
    vsnprintf(b->s + b->n, b->cap - b->n, fmt, ap);
    b->n += (size_t)k;
  }
  va_end(ap);
}

void rep_str_free(rep_str *b)
{
  free(b->s);
  memset(b, 0, sizeof *b);
}

static char *dup(const char *s)
{
  const size_t n = strlen(s) + 1;
  char *d = malloc(n);
  if (d)
    memcpy(d, s, n);
  return d;
}

/* ---- dictionary ---- */

void rep_vars_set(rep_vars *v, const char *key, const char *fmt, ...)
{
  char buf[2048];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  for (int i = 0; i < v->n; i++)
    if (!strcmp(v->key[i], key)) {
      char *nv = dup(buf);
      if (nv) {
        free(v->val[i]);
        v->val[i] = nv;
      }
      return;
    }
  if (v->n == v->cap) {
    const int cap = v->cap ? 2 * v->cap : 256;
    char **nk = realloc(v->key, sizeof *nk * (size_t)cap);
    if (!nk)
      return;
    v->key = nk;
    char **nv = realloc(v->val, sizeof *nv * (size_t)cap);
    if (!nv)
      return;
    v->val = nv;
    v->cap = cap;
  }
  v->key[v->n] = dup(key);
  v->val[v->n] = dup(buf);
  if (v->key[v->n] && v->val[v->n])
    v->n++;
}

void rep_vars_num(rep_vars *v, const char *key, double x)
{
  if (isfinite(x))
    rep_vars_set(v, key, "%.4g", x);
  else
    rep_vars_set(v, key, "n/a");
}

const char *rep_vars_get(const rep_vars *v, const char *key)
{
  for (int i = 0; i < v->n; i++)
    if (!strcmp(v->key[i], key))
      return v->val[i];
  return NULL;
}

void rep_vars_free(rep_vars *v)
{
  for (int i = 0; i < v->n; i++) {
    free(v->key[i]);
    free(v->val[i]);
  }
  free(v->key);
  free(v->val);
  memset(v, 0, sizeof *v);
}

char *rep_expand(rep_vars *v, const char *text)
{
  rep_str out = {0};
  rep_str_printf(&out, "%s", "");
  for (const char *p = text; *p;) {
    const char *o = strchr(p, '{'), *c = o ? strchr(o, '}') : NULL;
    if (!o || !c || c - o > 120) {
      rep_str_printf(&out, "%s", p);
      break;
    }
    rep_str_printf(&out, "%.*s", (int)(o - p), p);
    char key[128];
    snprintf(key, sizeof key, "%.*s", (int)(c - o - 1), o + 1);
    const char *val = rep_vars_get(v, key);
    if (!val)
      v->missing++;
    rep_str_printf(&out, val ? "%s" : "{%s?}", val ? val : key);
    p = c + 1;
  }
  return out.s;
}

/* ---- document ---- */

static rep_block *add(rep_doc *d, int kind)
{
  if (d->n == d->cap) {
    const int cap = d->cap ? 2 * d->cap : 64;
    rep_block *nb = realloc(d->b, sizeof *nb * (size_t)cap);
    if (!nb)
      return NULL;
    d->b = nb;
    d->cap = cap;
  }
  rep_block *b = &d->b[d->n++];
  memset(b, 0, sizeof *b);
  b->kind = kind;
  return b;
}

void rep_doc_head(rep_doc *d, int level, const char *id, const char *text)
{
  rep_block *b = add(d, REP_B_HEAD);
  if (!b)
    return;
  b->level = level;
  snprintf(b->id, sizeof b->id, "%s", id ? id : "");
  b->text = dup(text);
}

void rep_doc_para(rep_doc *d, const char *text)
{
  rep_block *b = add(d, REP_B_PARA);
  if (b)
    b->text = dup(text);
}

void rep_doc_toc(rep_doc *d)
{
  add(d, REP_B_TOC);
}

void rep_doc_fig(rep_doc *d, const char *name, const char *caption, int failed)
{
  rep_block *b = add(d, REP_B_FIG);
  if (!b)
    return;
  snprintf(b->id, sizeof b->id, "%s", name);
  b->text = dup(caption ? caption : "");
  b->failed = failed;
}

rep_table *rep_doc_table(rep_doc *d, int ncol, const char *const *head)
{
  rep_block *b = add(d, REP_B_TABLE);
  rep_table *t = b ? calloc(1, sizeof *t) : NULL;
  if (!t)
    return NULL;
  b->tab = t;
  t->ncol = ncol;
  rep_str h = {0};
  for (int c = 0; c < ncol; c++)
    rep_str_printf(&h, "%s%s", c ? "\t" : "", head[c]);
  rep_table_row(t, REP_ROW_HEAD, "%s", h.s ? h.s : "");
  rep_str_free(&h);
  return t;
}

void rep_table_row(rep_table *t, int cls, const char *fmt, ...)
{
  if (!t)
    return;
  char buf[4096];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  char **nc = realloc(t->cell, sizeof *nc * (size_t)((t->nrow + 1) * t->ncol));
  int *ncls = realloc(t->cls, sizeof *ncls * (size_t)(t->nrow + 1));
  if (nc)
    t->cell = nc;
  if (ncls)
    t->cls = ncls;
  if (!nc || !ncls)
    return;
  char *s = buf;
  for (int c = 0; c < t->ncol; c++) {
    char *tab = s ? strchr(s, '\t') : NULL;
    if (tab)
      *tab = '\0';
    t->cell[t->nrow * t->ncol + c] = dup(s ? s : "");
    s = tab ? tab + 1 : NULL;
  }
  t->cls[t->nrow++] = cls;
}

void rep_doc_free(rep_doc *d)
{
  for (int i = 0; i < d->n; i++) {
    rep_table *t = d->b[i].tab;
    if (t) {
      for (int k = 0; k < t->nrow * t->ncol; k++)
        free(t->cell[k]);
      free(t->cell);
      free(t->cls);
      free(t);
    }
    free(d->b[i].text);
  }
  free(d->b);
  memset(d, 0, sizeof *d);
}

/* One paragraph: to the caption if it is one, else to the document. */
static void template_para(rep_doc *d, rep_vars *v, const char *text, char **caption)
{
  char *e = rep_expand(v, text);
  if (caption && e && !strncmp(e, "caption: ", 9)) {
    free(*caption);
    *caption = dup(e + 9);
  } else
    rep_doc_para(d, e ? e : "");
  free(e);
}

int rep_doc_template(rep_doc *d, rep_vars *v, const char *path, char **title, char **caption)
{
  if (title)
    *title = NULL;
  if (caption)
    *caption = NULL;
  char *txt = ver_io_slurp(path, NULL, 1 << 20);
  if (!txt) {
    char msg[1200];
    snprintf(msg, sizeof msg, "(the text of this section is missing: %s cannot be read)", path);
    rep_doc_para(d, msg);
    return -1;
  }
  char *body = txt;
  if (!strncmp(txt, "# ", 2)) {
    char *nl = strchr(txt, '\n');
    if (nl)
      *nl = '\0';
    if (title)
      *title = rep_expand(v, txt + 2);
    body = nl ? nl + 1 : txt + strlen(txt);
  }
  /* paragraphs: blank lines apart; lines inside one are joined with a space */
  rep_str para = {0};
  for (char *line = body; line && *line;) {
    char *nl = strchr(line, '\n');
    if (nl)
      *nl = '\0';
    const int blank = strspn(line, " \t") == strlen(line);
    if (!blank)
      rep_str_printf(&para, "%s%s", para.n ? " " : "", line);
    if ((blank || !nl) && para.n) {
      template_para(d, v, para.s, caption);
      para.n = 0;
    }
    line = nl ? nl + 1 : NULL;
  }
  if (para.n)
    template_para(d, v, para.s, caption);
  rep_str_free(&para);
  free(txt);
  return 0;
}

/* ---- Markdown ---- */

static void md_cell(FILE *f, const char *s)
{
  for (; *s; s++)
    fputs(*s == '|' ? "\\|" : (char[2]){*s, 0}, f);
}

int rep_doc_markdown(const rep_doc *d, FILE *f)
{
  static const char *const mark[] = {"", "pass", "FAIL", "known-limit", ""};
  for (int i = 0; i < d->n; i++) {
    const rep_block *b = &d->b[i];
    if (b->kind == REP_B_HEAD)
      fprintf(f, "%s %s\n\n", b->level <= 1 ? "#" : b->level == 2 ? "##" : "###", b->text);
    else if (b->kind == REP_B_TOC) {
      fputs("Contents:", f);
      for (int j = 0, k = 0; j < d->n; j++)
        if (d->b[j].kind == REP_B_HEAD && d->b[j].level == 2)
          fprintf(f, "%s [%s](#%s)", k++ ? " ·" : "", d->b[j].text, d->b[j].id);
      fputs("\n\n", f);
    }
    else if (b->kind == REP_B_PARA)
      fprintf(f, "%s\n\n", b->text);
    else if (b->kind == REP_B_FIG)
      fprintf(f, "![%s](%s.png)\n\n*%s*%s\n\n", b->id, b->id, b->text,
              b->failed ? " (gnuplot failed for this figure; see logs/)" : "");
    else if (b->kind == REP_B_TABLE && b->tab) {
      const rep_table *t = b->tab;
      for (int r = 0; r < t->nrow; r++) {
        fputs("|", f);
        for (int c = 0; c < t->ncol; c++) {
          fputs(" ", f);
          md_cell(f, t->cell[r * t->ncol + c]);
          fputs(" |", f);
        }
        fputs("\n", f);
        if (r == 0) {
          fputs("|", f);
          for (int c = 0; c < t->ncol; c++)
            fputs("---|", f);
          fputs("\n", f);
        }
      }
      (void)mark;
      fputs("\n", f);
    }
  }
  return ferror(f) ? -1 : 0;
}

/* ---- HTML ---- */

static void esc(FILE *f, const char *s)
{
  for (; s && *s; s++) {
    if (*s == '<')
      fputs("&lt;", f);
    else if (*s == '>')
      fputs("&gt;", f);
    else if (*s == '&')
      fputs("&amp;", f);
    else if (*s == '"')
      fputs("&quot;", f);
    else
      fputc(*s, f);
  }
}

/* Text with Markdown code spans: `x` becomes <code>x</code> (code 1) or x (code 0, for
 * titles and attributes), so that no backtick shows. */
static void esc_code(FILE *f, const char *s, int code)
{
  int open = 0;
  for (; s && *s; s++) {
    if (*s == '`') {
      if (code)
        fputs(open ? "</code>" : "<code>", f);
      open = !open;
    } else
      esc(f, (char[2]){*s, 0});
  }
  if (open && code)
    fputs("</code>", f);
}

static void html_table(FILE *f, const rep_table *t)
{
  static const char *const cls[] = {"", "pass", "fail", "known", ""};
  fputs("<table>\n", f);
  for (int r = 0; r < t->nrow; r++) {
    const int k = t->cls[r];
    if (k > 0 && k < 4)
      fprintf(f, "<tr class=\"%s\">", cls[k]);
    else
      fputs("<tr>", f);
    for (int c = 0; c < t->ncol; c++) {
      fputs(r == 0 ? "<th>" : "<td>", f);
      esc_code(f, t->cell[r * t->ncol + c], 1);
      fputs(r == 0 ? "</th>" : "</td>", f);
    }
    fputs("</tr>\n", f);
  }
  fputs("</table>\n", f);
}

int rep_doc_html(const rep_doc *d, FILE *f, const char *title)
{
  fputs("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>", f);
  esc_code(f, title, 0);
  fputs("</title>\n<style>body{font-family:sans-serif;max-width:1100px;margin:auto;padding:1em;line-height:1.4}"
        "img{max-width:100%;border:1px solid #ccc}td,th{border:1px solid #ccc;padding:2px 6px;font-size:90%}"
        "table{border-collapse:collapse;margin:0.5em 0 1em}tr.fail td{background:#f8c8c8}"
        "tr.pass td{background:#d8f0d8}tr.known td{background:#fff0b8}figcaption{font-style:italic}"
        "nav{margin:0.5em 0 1em;padding:0.4em 0.6em;background:#f4f4f4;font-size:95%}code{background:#f0f0f0}"
        "</style></head><body>\n", f);
  for (int i = 0; i < d->n; i++) {
    const rep_block *b = &d->b[i];
    if (b->kind == REP_B_HEAD) {
      const int l = b->level < 1 ? 1 : b->level > 3 ? 3 : b->level;
      fprintf(f, "<h%d id=\"%s\">", l, b->id);
      esc_code(f, b->text, 1);
      fprintf(f, "</h%d>\n", l);
    } else if (b->kind == REP_B_TOC) {
      fputs("<nav><b>Contents:</b>", f);
      for (int j = 0, k = 0; j < d->n; j++)
        if (d->b[j].kind == REP_B_HEAD && d->b[j].level == 2) {
          /* the heading up to its colon ("Fig. 6(a)"), the whole of it where it has none;
           * the heading itself is the link's tooltip */
          const char *t = d->b[j].text ? d->b[j].text : "";
          const char *colon = strchr(t, ':');
          char shortt[160];
          snprintf(shortt, sizeof shortt, "%.*s", colon ? (int)(colon - t) : (int)strlen(t), t);
          fprintf(f, "%s <a href=\"#%s\" title=\"", k++ ? " &middot;" : "", d->b[j].id);
          esc_code(f, t, 0);
          fputs("\">", f);
          esc_code(f, shortt, 1);
          fputs("</a>", f);
        }
      fputs("</nav>\n", f);
    } else if (b->kind == REP_B_PARA) {
      fputs("<p>", f);
      esc_code(f, b->text, 1);
      fputs("</p>\n", f);
    } else if (b->kind == REP_B_FIG) {
      fprintf(f, "<figure><a href=\"%s.svg\"><img src=\"%s.png\" alt=\"%s\"></a><figcaption>", b->id, b->id, b->id);
      esc_code(f, b->text, 1);
      if (b->failed)
        fputs(" <b>(gnuplot failed for this figure; see logs/)</b>", f);
      fputs("</figcaption></figure>\n", f);
    } else if (b->kind == REP_B_TABLE && b->tab)
      html_table(f, b->tab);
  }
  fputs("</body></html>\n", f);
  return ferror(f) ? -1 : 0;
}
