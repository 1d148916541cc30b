/* A client written from idl/gearcoupling.idl and docs/protocol.md alone: plain C over the
 * Cyclone DDS C API and the idlc-generated types, none of this project's C++ (issue 40: "a
 * foreign client can use the batch topics"). It follows "The rules a client follows" (1-5, 8),
 * sends one BatchRequest of induced moments on nrel_upwind and on a coupling the service does
 * not have, with good cases between bad ones, and checks that every case is answered in place:
 * its status and field as docs/protocol.md "Batches" names them, a result for the good ones.
 *
 *   foreign_batch_client DOMAIN      exit 0 when every check holds, 1 otherwise (the reason on
 *                                    stderr), 2 when no service answered within 20 s
 *
 * The caller chooses the domain and the Cyclone configuration (CYCLONEDDS_URI: loopback). */
#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "dds/dds.h"
#include "gearcoupling.h"

#define TIMEOUT_S 20.0

static int failures = 0;

static void fail(const char* what, uint32_t case_index) {
  fprintf(stderr, "foreign client: case %" PRIu32 ": %s\n", case_index, what);
  ++failures;
}

static double now_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static dds_entity_t must(dds_entity_t entity, const char* what) {
  if (entity < 0) {
    fprintf(stderr, "foreign client: %s: %s\n", what, dds_strretcode(entity));
    exit(1);
  }
  return entity;
}

/* Rule 2: a subscriber (or publisher) in one partition. */
static dds_qos_t* partition_qos(const char* partition) {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_partition1(qos, partition);
  return qos;
}

/* QoS table of docs/protocol.md: requests and reply readers RELIABLE (10 s), KEEP_ALL, VOLATILE. */
static dds_qos_t* request_reply_qos(void) {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
  return qos;
}

/* Rule 3: the first live, accepting instance's status. */
static bool find_instance(dds_entity_t status_reader, uint64_t* instance_id, char* partition,
                          size_t partition_size) {
  void* samples[1] = {NULL};
  dds_sample_info_t info[1];
  const dds_return_t n = dds_read(status_reader, samples, info, 1, 1);
  bool found = false;
  if (n > 0 && info[0].valid_data && info[0].instance_state == DDS_IST_ALIVE) {
    const gearcoupling_ServiceStatus* status = samples[0];
    if (status->accepting) {
      *instance_id = status->instance_id;
      snprintf(partition, partition_size, "%s", status->request_partition);
      found = true;
    }
  }
  if (n > 0) dds_return_loan(status_reader, samples, n);
  return found;
}

/* Rule 4, second half: the reply reader has matched a writer whose USER_DATA is exactly the 16
 * hexadecimal digits of the instance id, without a NUL. */
static bool reply_writer_matched(dds_entity_t reply_reader, uint64_t instance_id) {
  char expected[17];
  snprintf(expected, sizeof expected, "%016" PRIx64, instance_id);
  dds_instance_handle_t handles[16];
  const dds_return_t n = dds_get_matched_publications(reply_reader, handles, 16);
  bool matched = false;
  for (dds_return_t i = 0; i < n && !matched; ++i) {
    dds_builtintopic_endpoint_t* endpoint = dds_get_matched_publication_data(reply_reader, handles[i]);
    if (endpoint == NULL) continue;
    void* value = NULL;
    size_t size = 0;
    if (dds_qget_userdata(endpoint->qos, &value, &size) && size == 16 &&
        memcmp(value, expected, 16) == 0) {
      matched = true;
    }
    dds_free(value);
    dds_builtintopic_free_endpoint(endpoint);
  }
  return matched;
}

static void check_case(const gearcoupling_BatchCaseReply* reply, uint32_t index,
                       gearcoupling_ReplyStatus status, const char* field) {
  if (reply->status != status) {
    char what[512];
    snprintf(what, sizeof what, "status %d, expected %d (field '%s', message '%s')",
             (int)reply->status, (int)status, reply->field, reply->message);
    fail(what, index);
    return;
  }
  if (strcmp(reply->field, field) != 0) {
    char what[512];
    snprintf(what, sizeof what, "field '%s', expected '%s'", reply->field, field);
    fail(what, index);
  }
  if (status == gearcoupling_STATUS_OK) {
    if (reply->result._d != gearcoupling_BATCH_INDUCED_MOMENTS) fail("result of another calculation", index);
    const gearcoupling_InducedMomentsResult* m = &reply->result._u.induced_moments;
    /* A misaligned coupling under torque bends its shafts: a finite, non-zero moment. */
    if (!(isfinite(m->magnitude_nm) && m->magnitude_nm > 0.0)) fail("no induced moment", index);
    if (m->teeth_summed <= 0) fail("no tooth summed (eqs 42-43)", index);
  } else if (strlen(reply->message) == 0) {
    fail("an error without a message", index);
  }
}

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: foreign_batch_client DOMAIN\n");
    return 1;
  }
  const dds_domainid_t domain = (dds_domainid_t)atoi(argv[1]);
  /* Rule 1: a random, non-zero client id; requests numbered from 1. */
  srand((unsigned)(getpid() ^ (unsigned)time(NULL)));
  const uint64_t client_id = ((uint64_t)rand() << 33 | (uint64_t)rand() << 2 | 1u);

  const dds_entity_t participant = must(dds_create_participant(domain, NULL, NULL), "participant");
  const dds_entity_t status_topic = must(
      dds_create_topic(participant, &gearcoupling_ServiceStatus_desc, "gearcoupling/status", NULL, NULL),
      "status topic");
  const dds_entity_t request_topic = must(
      dds_create_topic(participant, &gearcoupling_BatchRequest_desc, "gearcoupling/batch/request", NULL, NULL),
      "request topic");
  const dds_entity_t reply_topic = must(
      dds_create_topic(participant, &gearcoupling_BatchReply_desc, "gearcoupling/batch/reply", NULL, NULL),
      "reply topic");

  /* Rule 2: the reply reader in gearcoupling.reply.<client id>, the status reader. */
  char reply_partition[64];
  snprintf(reply_partition, sizeof reply_partition, "gearcoupling.reply.%016" PRIx64, client_id);
  dds_qos_t* qos = partition_qos(reply_partition);
  const dds_entity_t reply_subscriber = must(dds_create_subscriber(participant, qos, NULL), "subscriber");
  dds_delete_qos(qos);
  qos = request_reply_qos();
  const dds_entity_t reply_reader = must(dds_create_reader(reply_subscriber, reply_topic, qos, NULL), "reply reader");
  dds_delete_qos(qos);

  qos = partition_qos("gearcoupling");
  const dds_entity_t status_subscriber = must(dds_create_subscriber(participant, qos, NULL), "subscriber");
  dds_delete_qos(qos);
  qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  const dds_entity_t status_reader = must(dds_create_reader(status_subscriber, status_topic, qos, NULL), "status reader");
  dds_delete_qos(qos);

  /* Rule 3, then rule 4: a request writer in the instance's partition, matched both ways. */
  const double start = now_s();
  uint64_t instance_id = 0;
  char request_partition[128];
  while (!find_instance(status_reader, &instance_id, request_partition, sizeof request_partition)) {
    if (now_s() - start > TIMEOUT_S) {
      fprintf(stderr, "foreign client: no live instance on domain %d\n", (int)domain);
      return 2;
    }
    dds_sleepfor(DDS_MSECS(20));
  }
  qos = partition_qos(request_partition);
  const dds_entity_t publisher = must(dds_create_publisher(participant, qos, NULL), "publisher");
  dds_delete_qos(qos);
  qos = request_reply_qos();
  const dds_entity_t request_writer = must(dds_create_writer(publisher, request_topic, qos, NULL), "request writer");
  dds_delete_qos(qos);
  for (;;) {
    dds_publication_matched_status_t matched;
    dds_get_publication_matched_status(request_writer, &matched);
    if (matched.current_count > 0 && reply_writer_matched(reply_reader, instance_id)) break;
    if (now_s() - start > TIMEOUT_S) {
      fprintf(stderr, "foreign client: instance %016" PRIx64 " not matched both ways\n", instance_id);
      return 2;
    }
    dds_sleepfor(DDS_MSECS(20));
  }

  /* The batch: nrel_upwind (0) and a name the catalogue lacks (1); the core's default options. */
  gearcoupling_CouplingRef couplings[2];
  memset(couplings, 0, sizeof couplings);
  couplings[0]._d = gearcoupling_COUPLING_FROM_CATALOGUE;
  couplings[0]._u.catalogue_name = "nrel_upwind";
  couplings[1]._d = gearcoupling_COUPLING_FROM_CATALOGUE;
  couplings[1]._u.catalogue_name = "no_such_coupling";
  const gearcoupling_BatchCase cases[] = {
      {0, {1.5e6, 0.0079, 0.0, 0.12}},  /* good: 1.5 MN m, 0.45 deg, mu 0.12 */
      {0, {-1.0, 0.0079, 0.0, 0.12}},   /* a negative torque */
      {1, {1.5e6, 0.0079, 0.0, 0.12}},  /* the unknown coupling */
      {7, {1.5e6, 0.0079, 0.0, 0.12}},  /* an index past the two couplings */
      {0, {1.5e6, 0.5, 0.0, 0.12}},     /* 29 deg: far beyond the jam angle (0.75 deg) */
      {0, {1.0e6, 0.004, 1.0, 0.1}},    /* good again, after the bad ones */
  };
  const uint32_t case_count = sizeof cases / sizeof cases[0];
  gearcoupling_BatchRequest request;
  memset(&request, 0, sizeof request);
  request.correlation.client_id = client_id;
  request.correlation.sequence_number = 1;
  request.calculation = gearcoupling_BATCH_INDUCED_MOMENTS;
  request.couplings._buffer = couplings;
  request.couplings._length = request.couplings._maximum = 2;
  request.options.load_sharing.tolerance = 1e-9;
  request.options.load_sharing.max_iterations = 100;
  request.options.slices = 20;
  request.options.spacing_error_m = 0.0;
  request.options.min_load_fraction = 0.9;
  request.options.continuous_quarter_sums = false;
  request.cases._buffer = (gearcoupling_BatchCase*)cases;
  request.cases._length = request.cases._maximum = case_count;
  must(dds_write(request_writer, &request), "write");

  /* Rule 5 and 8: the reply with our correlation, within a deadline. */
  for (;;) {
    void* samples[1] = {NULL};
    dds_sample_info_t info[1];
    const dds_return_t n = dds_take(reply_reader, samples, info, 1, 1);
    if (n > 0 && info[0].valid_data) {
      const gearcoupling_BatchReply* reply = samples[0];
      if (reply->correlation.client_id == client_id && reply->correlation.sequence_number == 1) {
        if (reply->status != gearcoupling_STATUS_OK) {
          fprintf(stderr, "foreign client: the batch was refused whole: %d %s: %s\n",
                  (int)reply->status, reply->field, reply->message);
          ++failures;
        } else if (reply->result.cases._length != case_count) {
          fprintf(stderr, "foreign client: %" PRIu32 " answers to %" PRIu32 " cases\n",
                  reply->result.cases._length, case_count);
          ++failures;
        } else {
          const gearcoupling_BatchCaseReply* c = reply->result.cases._buffer;
          check_case(&c[0], 0, gearcoupling_STATUS_OK, "");
          check_case(&c[1], 1, gearcoupling_STATUS_INVALID_INPUT, "operating_point.torque_nm");
          check_case(&c[2], 2, gearcoupling_STATUS_UNKNOWN_COUPLING, "coupling.catalogue_name");
          check_case(&c[3], 3, gearcoupling_STATUS_INVALID_INPUT, "coupling");
          check_case(&c[4], 4, gearcoupling_STATUS_INVALID_INPUT, "operating_point.misalignment_rad");
          check_case(&c[5], 5, gearcoupling_STATUS_OK, "");
        }
        dds_return_loan(reply_reader, samples, n);
        break;
      }
    }
    if (n > 0) dds_return_loan(reply_reader, samples, n);
    if (now_s() - start > TIMEOUT_S) {
      fprintf(stderr, "foreign client: no reply within %.0f s\n", TIMEOUT_S);
      return 2;
    }
    dds_sleepfor(DDS_MSECS(5));
  }
  dds_delete(participant);
  if (failures == 0) printf("foreign client: %" PRIu32 " cases answered in place\n", case_count);
  return failures == 0 ? 0 : 1;
}
