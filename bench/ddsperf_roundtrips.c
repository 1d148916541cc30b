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
 * The lines are kept in a 4 MiB buffer and written at exit, so the run makes no write of its own. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <dds/dds.h>

typedef int32_t (*take_fn) (dds_entity_t, void **, dds_sample_info_t *, size_t, uint32_t);

static FILE *out;
static char out_buffer[4 << 20];

/* The readers seen, whether each is the pong reader: a take costs no name lookup after the first.
   Takes come from several of Cyclone's threads (listeners), hence the lock. */
#define MAX_READERS 64
static struct { dds_entity_t reader; int is_pong; } readers[MAX_READERS];
static int nreaders;
static pthread_mutex_t readers_lock = PTHREAD_MUTEX_INITIALIZER;

static int is_pong_reader_locked (dds_entity_t reader)
{
  for (int i = 0; i < nreaders; i++)
    if (readers[i].reader == reader)
      return readers[i].is_pong;
  char name[64] = "";
  const dds_entity_t topic = dds_get_topic (reader);
  const int is_pong = topic > 0 && dds_get_name (topic, name, sizeof (name)) > 0 &&
                      strncmp (name, "DDSPerf", 7) == 0 && strstr (name, "Pong") != NULL;
  if (nreaders < MAX_READERS)
  {
    readers[nreaders].reader = reader;
    readers[nreaders].is_pong = is_pong;
    nreaders++;
  }
  return is_pong;
}

static int is_pong_reader (dds_entity_t reader)
{
  pthread_mutex_lock (&readers_lock);
  const int is_pong = is_pong_reader_locked (reader);
  pthread_mutex_unlock (&readers_lock);
  return is_pong;
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
  if (n > 0 && is_pong_reader (reader))
    record (si, n);
  return n;
}

__attribute__ ((constructor)) static void open_output (void)
{
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
