/*
 * gw_io_hash_memo.c: the content hashes (FNV-1a 64, gw_io_hash.c) of files
 * read again and again in one pass, kept while stat says each file is the
 * one that was hashed (gw_io_impl.h: device, inode, size, modification and
 * status-change times), so that a sweep hashes its sample once and not once
 * for each case. No units.
 */
#define _POSIX_C_SOURCE 200809L /* st_mtim, st_ctim, strdup, clock_gettime */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "gw_io_impl.h"

/* What of a stat the memo compares. */
typedef struct stamp {
    dev_t dev;
    ino_t ino;
    long long size, ms, mns, cs, cns;
} stamp;

static int stamp_of(const char *path, stamp *s)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return 0;
    *s = (stamp){st.st_dev, st.st_ino, (long long)st.st_size, (long long)st.st_mtim.tv_sec,
                 (long long)st.st_mtim.tv_nsec, (long long)st.st_ctim.tv_sec, (long long)st.st_ctim.tv_nsec};
    return 1;
}

static int stamp_same(const stamp *a, const stamp *b)
{
    return a->dev == b->dev && a->ino == b->ino && a->size == b->size && a->ms == b->ms && a->mns == b->mns &&
           a->cs == b->cs && a->cns == b->cns;
}

static int seen_is(const struct gw_hash_seen *e, const stamp *s)
{
    const stamp k = {e->dev, e->ino, e->size, e->mtime_s, e->mtime_ns, e->ctime_s, e->ctime_ns};
    return stamp_same(&k, s);
}

/* 1 when both of the file's times were GW_HASH_MEMO_SETTLE_S seconds or more
 * before now (at the start of its hash): a later write moves its
 * status-change time on, even on a file system that keeps whole seconds */
static int settled(const stamp *s, const struct timespec *now)
{
    const long long t = (long long)now->tv_sec - GW_HASH_MEMO_SETTLE_S;
    return s->ms < t && s->cs < t;
}

/* m's entry for path (NULL: none) */
static struct gw_hash_seen *find(gw_hash_memo *m, const char *path)
{
    for (long i = 0; i < m->n; i++)
        if (strcmp(m->seen[i].path, path) == 0)
            return &m->seen[i];
    return NULL;
}

/* path's entry kept as s with hash h; nothing kept when m cannot grow */
static void keep(gw_hash_memo *m, const char *path, const stamp *s, unsigned long long h)
{
    struct gw_hash_seen *e = find(m, path);
    if (!e) {
        if (m->n == m->cap) {
            const long cap = m->cap ? 2 * m->cap : 8;
            struct gw_hash_seen *p = realloc(m->seen, (size_t)cap * sizeof *p);
            if (!p)
                return;
            m->seen = p, m->cap = cap;
        }
        char *copy = strdup(path);
        if (!copy)
            return;
        e = &m->seen[m->n++];
        e->path = copy;
    }
    e->dev = s->dev, e->ino = s->ino, e->size = s->size;
    e->mtime_s = s->ms, e->mtime_ns = s->mns, e->ctime_s = s->cs, e->ctime_ns = s->cns;
    e->hash = h;
}

int gw_io_hash_memo(gw_hash_memo *m, const char *path, gw_hash_memo_fn fn, unsigned long long *h, gw_err *err)
{
    if (!path || !fn || !h)
        return gw_err_set(err, GW_EINVAL, "gw_io_hash_memo: %s is NULL", !path ? "path" : !fn ? "fn" : "h");
    if (!m)
        return fn(path, h, err);
    stamp before, after;
    const int known = stamp_of(path, &before);
    struct gw_hash_seen *e = known ? find(m, path) : NULL;
    if (e && seen_is(e, &before)) {
        *h = e->hash;
        return GW_OK;
    }
    struct timespec now;
    const int timed = clock_gettime(CLOCK_REALTIME, &now) == 0;
    m->hashed++;
    const int rc = fn(path, h, err);
    if (rc == GW_OK && known && timed && settled(&before, &now) && stamp_of(path, &after) &&
        stamp_same(&before, &after))
        keep(m, path, &before, *h);
    else if (e) /* the kept hash is no longer the file's: never given again */
        e->size = -1;
    return rc;
}

void gw_io_hash_memo_free(gw_hash_memo *m)
{
    if (!m)
        return;
    for (long i = 0; i < m->n; i++)
        free(m->seen[i].path);
    free(m->seen);
    memset(m, 0, sizeof *m);
}
