/* Every round trip of `ddsperf ping`, not only its per-second summaries (bench/control_loop.sh).
 *
 *   GC_DDSPERF_ROUNDTRIPS=FILE LD_PRELOAD=libgc_ddsperf_roundtrips.so ddsperf ping 1000Hz
 *
 * ddsperf prints, once a second, the 50 %, 90 % and 99 % points and the maximum of half the
 * round trip; p99.9 over a run, and the share over 1 ms, cannot be had from those. Preloaded into
 * ddsperf ping, this wraps dds_take: for every valid sample taken from the pong reader (topic
 * DDSPerf?Pong*) it records "T_S ROUND_TRIP_US", T_S the CLOCK_MONOTONIC time the ping was sent
 * (seconds), the round trip the time of the take minus the pong's source timestamp, which ping
 * set when it wrote the ping (pong writes it back): the time ddsperf takes in process_pong, the
 * whole round trip, not its half. bench/latency_stats.py reads the file as it reads the service's.
 * The lines are kept in a 4 MiB buffer and written at exit, so the run makes no write of its own.
 *
 * With GC_DDSPERF_PING_TIMES=FILE it also wraps dds_write_ts, with which ping writes its pings,
 * and keeps in FILE (8 bytes, mapped shared) the CLOCK_MONOTONIC time (ns) of the latest ping.
 * gc_bench_control_loop --phase-of FILE reads it to put its ticks between ping's
 * (bench/lib/control_loop.sh). Ping's schedule is fixed, but it starts again from any ping sent
 * over half a period late (ddsperf.c, maybe_send_new_ping), so the latest ping is what counts. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include <dds/dds.h>

typedef int32_t (*take_fn) (dds_entity_t, void **, dds_sample_info_t *, size_t, uint32_t);
typedef dds_return_t (*write_ts_fn) (dds_entity_t, const void *, dds_time_t);

static FILE *out;
static char out_buffer[4 << 20];

/* The readers and writers seen, whether each is of a topic DDSPerf*KIND* (readers: Pong, writers:
   Ping): a take or a write costs no name lookup after the first. Takes come from several of
   Cyclone's threads (listeners), hence the lock. */
#define MAX_ENTITIES 64
static struct { dds_entity_t entity; int of_kind; } entities[MAX_ENTITIES];
static int nentities;
static pthread_mutex_t entities_lock = PTHREAD_MUTEX_INITIALIZER;

static int of_topic_locked (dds_entity_t entity, const char *kind)
{
  for (int i = 0; i < nentities; i++)
    if (entities[i].entity == entity)
      return entities[i].of_kind;
  char name[64] = "";
  const dds_entity_t topic = dds_get_topic (entity);
  const int of_kind = topic > 0 && dds_get_name (topic, name, sizeof (name)) > 0 &&
                      strncmp (name, "DDSPerf", 7) == 0 && strstr (name, kind) != NULL;
  if (nentities < MAX_ENTITIES)
  {
    entities[nentities].entity = entity;
    entities[nentities].of_kind = of_kind;
    nentities++;
  }
  return of_kind;
}

static int of_topic (dds_entity_t entity, const char *kind)
{
  pthread_mutex_lock (&entities_lock);
  const int of_kind = of_topic_locked (entity, kind);
  pthread_mutex_unlock (&entities_lock);
  return of_kind;
}

static double monotonic_s (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec + (double) t.tv_nsec * 1e-9;
}

static void record (const dds_sample_info_t *si, int32_t n)
{
  if (out == NULL)
    return;
  const dds_time_t now = dds_time ();
  const double now_s = monotonic_s ();
  for (int32_t i = 0; i < n; i++)
  {
    if (!si[i].valid_data)
      continue;
    const double round_trip_s = (double) (now - si[i].source_timestamp) * 1e-9;
    fprintf (out, "%.6f %.1f\n", now_s - round_trip_s, round_trip_s * 1e6);
  }
}

int32_t dds_take (dds_entity_t reader, void **buf, dds_sample_info_t *si, size_t bufsz, uint32_t maxs)
{
  static take_fn real_take;
  if (real_take == NULL)
    *(void **) &real_take = dlsym (RTLD_NEXT, "dds_take");  /* POSIX's way to a function pointer */
  const int32_t n = real_take (reader, buf, si, bufsz, maxs);
  if (n > 0 && of_topic (reader, "Pong"))
    record (si, n);
  return n;
}

/* GC_DDSPERF_PING_TIMES's 8 bytes, mapped: the latest ping's CLOCK_MONOTONIC time (ns). */
static int64_t *latest_ping_ns;

dds_return_t dds_write_ts (dds_entity_t writer, const void *data, dds_time_t timestamp)
{
  static write_ts_fn real_write_ts;
  if (real_write_ts == NULL)
    *(void **) &real_write_ts = dlsym (RTLD_NEXT, "dds_write_ts");
  /* Ping took the ping's timestamp before this call: what is done here counts in its round trip,
     so it is a look into the cache above (its name looked up at the first ping only), one clock
     read (vDSO) and one store. */
  if (latest_ping_ns != NULL && of_topic (writer, "Ping"))
  {
    struct timespec t;
    clock_gettime (CLOCK_MONOTONIC, &t);
    __atomic_store_n (latest_ping_ns, (int64_t) t.tv_sec * 1000000000 + t.tv_nsec, __ATOMIC_RELEASE);
  }
  return real_write_ts (writer, data, timestamp);
}

/* Maps GC_DDSPERF_PING_TIMES, 8 bytes of zeros until the first ping. */
static void map_ping_times (void)
{
  const char *path = getenv ("GC_DDSPERF_PING_TIMES");
  if (path == NULL)
    return;
  const int fd = open (path, O_RDWR | O_CREAT | O_TRUNC, 0644);
  void *p = MAP_FAILED;
  if (fd >= 0 && ftruncate (fd, sizeof (int64_t)) == 0)
    p = mmap (NULL, sizeof (int64_t), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (fd >= 0)
    close (fd);
  if (p == MAP_FAILED)
    fprintf (stderr, "GC_DDSPERF_PING_TIMES=%s: cannot map\n", path);
  else
    latest_ping_ns = p;
}

__attribute__ ((constructor)) static void open_output (void)
{
  map_ping_times ();
  const char *path = getenv ("GC_DDSPERF_ROUNDTRIPS");
  if (path == NULL)
    return;
  out = fopen (path, "w");
  if (out == NULL)
  {
    fprintf (stderr, "GC_DDSPERF_ROUNDTRIPS=%s: cannot write\n", path);
    return;
  }
  setvbuf (out, out_buffer, _IOFBF, sizeof (out_buffer));
}

__attribute__ ((destructor)) static void close_output (void)
{
  if (out != NULL)
    fclose (out);
  out = NULL;
}
