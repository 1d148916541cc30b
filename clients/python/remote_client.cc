// gearcoupling.Client: the calculations through gearcoupling-service (client/client.h,
// public methods only). Vectorised calls keep `in_flight` load cases' requests outstanding at
// once (the service spreads them over its threads and instances), the GIL released while waiting.
#include <chrono>
#include <deque>
#include <future>
#include <memory>

#include <pybind11/stl.h>

#include "clients/python/bindings.h"
#include "clients/python/case_arrays.h"
#include "clients/python/coupling_argument.h"
#include "clients/python/result_object.h"
#include "client/client.h"
#include "protocol/dds_config.h"
#include "core/model_error.h"

namespace py = pybind11;

namespace gc::python {
namespace {

using protocol::Calculation;

struct Client {
  std::shared_ptr<client::Client> client;
};

protocol::CouplingRef coupling_ref(const RemoteCoupling& coupling) {
  if (coupling.catalogue_name) return protocol::CatalogueName{*coupling.catalogue_name};
  return coupling.inline_coupling->geometry->definition();
}

std::shared_ptr<client::Client> make_client(int domain, double timeout_s) {
  if (!(timeout_s > 0.0 && timeout_s <= 86400.0)) {
    throw InvalidInput("timeout", timeout_s, "(0, 86400] s");
  }
  client::ClientOptions options;
  options.domain = domain;
  options.timeout = std::chrono::milliseconds(static_cast<long long>(timeout_s * 1000.0 + 0.5));
  py::gil_scoped_release release;
  return std::make_shared<client::Client>(options);
}

template <Calculation kCalculation>
auto call(const Client& self, const typename protocol::CalculationTypes<kCalculation>::Request& request) {
  py::gil_scoped_release release;
  return self.client->call<kCalculation>(request);
}

// ---- one case ---------------------------------------------------------------------------------

ToothContactResultObject tooth_contact(const Client& self, const CouplingArgument& coupling, double torque_nm,
                         double misalignment_rad, double direction_rad, double mu, int slices,
                         double tolerance, int max_iterations) {
  const RemoteCoupling c = remote_coupling_argument(coupling);
  const OperatingPoint point{torque_nm, misalignment_rad, direction_rad, mu};
  const ToothContact contact = call<Calculation::kToothContact>(
      self, {coupling_ref(c), point, contact_options(slices, tolerance, max_iterations)});
  return tooth_contact_result(c.name, point, contact);
}

// Both requests in flight at once, as the CLI's --remote does; the service computes the moments
// from the same contact.
analysis::LoadCase load_case(client::Client& client, const protocol::CouplingRef& ref,
                             const OperatingPoint& point, const ContactOptions& options) {
  // One deadline for both: the second does not wait for a service again after the first gave up.
  const auto deadline = client::Client::Clock::now() + client.options().timeout;
  auto contact = client.call_async<Calculation::kToothContact>({ref, point, options}, deadline);
  auto moments = client.call_async<Calculation::kInducedMoments>({ref, point, options}, deadline);
  return {contact.get(), moments.get()};
}

InducedMomentsResultObject induced_moments(const Client& self, const CouplingArgument& coupling, double torque_nm,
                           double misalignment_rad, double direction_rad, double mu, int slices,
                           double tolerance, int max_iterations) {
  const RemoteCoupling c = remote_coupling_argument(coupling);
  const OperatingPoint point{torque_nm, misalignment_rad, direction_rad, mu};
  const protocol::CouplingRef ref = coupling_ref(c);
  analysis::LoadCase result;
  {
    py::gil_scoped_release release;
    result = load_case(*self.client, ref, point, contact_options(slices, tolerance, max_iterations));
  }
  return induced_moments_result(c.name, point, result.contact, result.moments);
}

JamAngleResultObject jam_angle(const Client& self, const CouplingArgument& coupling) {
  const RemoteCoupling c = remote_coupling_argument(coupling);
  const protocol::JamAngleResult result = call<Calculation::kJamAngle>(self, {coupling_ref(c)});
  return jam_angle_result(c.name, result.jam, result.crown_radius_m, result.crown_radius_derived);
}

RestoringTorqueResultObject restoring_torque(const Client& self, const CouplingArgument& coupling) {
  const RemoteCoupling c = remote_coupling_argument(coupling);
  return restoring_torque_result(c.name, call<Calculation::kRestoringTorque>(self, {coupling_ref(c)}));
}

FrictionEstimateResultObject estimate_friction(const Client& self, const CouplingArgument& coupling, double torque_nm,
                             double misalignment_rad, double direction_rad,
                             double sensor_moment_y_nm, double sensor_moment_z_nm) {
  const RemoteCoupling c = remote_coupling_argument(coupling);
  const FrictionMeasurement measurement{torque_nm, misalignment_rad, direction_rad,
                                        sensor_moment_y_nm, sensor_moment_z_nm};
  return friction_estimate_result(
      c.name, measurement, call<Calculation::kFrictionEstimate>(self, {coupling_ref(c), measurement}));
}

// ---- many cases -------------------------------------------------------------------------------

// Sends case after case, keeping at most `in_flight` outstanding: when the window is full, the
// oldest case's replies are collected first. `send(i)` returns a callable giving case i's result
// (or throwing its error). After a Timeout (no service answering) nothing more is sent: each
// further case would wait the whole timeout too; the cases not sent fail with that Timeout. So
// does every case when no instance takes `calculation` within the timeout to begin with.
template <typename Result, typename Send>
CaseTableObject run_remote_cases(client::Client& client, Calculation calculation,
                                 const std::vector<Column<Result>>& columns, const CaseInputs& inputs,
                                 std::size_t in_flight, FailedCases failed, const Send& send) {
  if (in_flight < 1 || in_flight > 100000) {
    throw InvalidInput("in_flight", static_cast<double>(in_flight), "[1, 100000]");
  }
  CaseArrays<Result> arrays(columns, inputs, failed);
  const std::size_t count = inputs.size();
  {
    py::gil_scoped_release release;
    using Pending = decltype(send(std::size_t{0}));
    std::deque<std::pair<std::size_t, Pending>> window;
    std::exception_ptr timeout;
    if (!client.wait_for_service(calculation, client.options().timeout)) {
      timeout = std::make_exception_ptr(client::Timeout(protocol::no_instance_message(
          client.options().domain, client.options().timeout, client.dds_configuration())));
    }
    const auto record_failure = [&](std::size_t index) {
      try {
        throw;
      } catch (const client::Timeout&) {
        if (!timeout) timeout = std::current_exception();
        arrays.fail(index, std::current_exception());
      } catch (const std::exception&) {
        arrays.fail(index, std::current_exception());
      }
    };
    const auto collect_oldest = [&] {
      auto& [index, pending] = window.front();
      try {
        arrays.set(index, pending());
      } catch (...) {
        record_failure(index);
      }
      window.pop_front();
    };
    std::size_t i = 0;
    for (; i < count && !timeout; ++i) {
      if (window.size() >= in_flight) collect_oldest();
      try {
        window.emplace_back(i, send(i));
      } catch (...) {
        record_failure(i);
      }
    }
    while (!window.empty()) collect_oldest();
    for (; i < count; ++i) arrays.fail(i, timeout);
  }
  return arrays.finish();
}

// A future's result, called once.
template <typename T>
auto getter(std::future<T> future) {
  return [f = std::make_shared<std::future<T>>(std::move(future))] { return f->get(); };
}

CaseTableObject tooth_contact_many(const Client& self, const CouplingArgument& coupling,
                                   const ArrayArgument& torque_nm,
                                   const ArrayArgument& misalignment_rad,
                                   const ArrayArgument& direction_rad, int slices,
                            double tolerance, int max_iterations, std::size_t in_flight,
                            const std::string& errors) {
  const protocol::CouplingRef ref = coupling_ref(remote_coupling_argument(coupling));
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad"},
                      {torque_nm, misalignment_rad, direction_rad});
  const ContactOptions options = contact_options(slices, tolerance, max_iterations);
  client::Client& client = *self.client;
  return run_remote_cases(client, Calculation::kToothContact, tooth_contact_columns(), in,
                          in_flight, failed_cases_argument(errors),
                          [&](std::size_t i) {
                            const OperatingPoint point{in(0, i), in(1, i), in(2, i), 0.0};
                            return getter(client.call_async<Calculation::kToothContact>({ref, point, options}));
                          });
}

CaseTableObject induced_moments_many(const Client& self, const CouplingArgument& coupling,
                                     const ArrayArgument& torque_nm,
                                     const ArrayArgument& misalignment_rad,
                                     const ArrayArgument& direction_rad, const ArrayArgument& mu,
                                     int slices, double tolerance, int max_iterations, std::size_t in_flight,
                              const std::string& errors) {
  const protocol::CouplingRef ref = coupling_ref(remote_coupling_argument(coupling));
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad", "mu"},
                      {torque_nm, misalignment_rad, direction_rad, mu});
  const ContactOptions options = contact_options(slices, tolerance, max_iterations);
  if (in_flight < 1 || in_flight > 1000000) {
    throw InvalidInput("in_flight", static_cast<double>(in_flight), "[1, 1000000]");
  }
  client::Client& client = *self.client;
  CaseArrays<analysis::LoadCase> arrays(load_case_columns(), in, failed_cases_argument(errors));
  const std::size_t count = in.size();
  {
    py::gil_scoped_release release;
    // Load cases in batches (issue 40; Client::call_many: 4096 cases a request at most), up to
    // `in_flight` cases outstanding. After a Timeout nothing more is sent, as run_remote_cases.
    std::exception_ptr timeout;
    if (!client.wait_for_service(Calculation::kBatch, client.options().timeout)) {
      timeout = std::make_exception_ptr(client::Timeout(protocol::no_instance_message(
          client.options().domain, client.options().timeout, client.dds_configuration())));
    }
    std::vector<protocol::BatchCase> cases;
    std::size_t start = 0;
    for (; start < count && !timeout; start += in_flight) {
      const std::size_t end = std::min(count, start + in_flight);
      cases.clear();
      for (std::size_t i = start; i < end; ++i) {
        cases.push_back({0, {in(0, i), in(1, i), in(2, i), in(3, i)}});
      }
      std::vector<protocol::BatchCaseReply> replies;
      try {
        replies = client.call_many(protocol::BatchCalculation::kLoadCase, {ref}, options, cases);
      } catch (...) {  // the whole block failed: a Timeout stops the call, anything else the block
        const std::exception_ptr error = std::current_exception();
        try {
          throw;
        } catch (const client::Timeout&) {
          timeout = error;
        } catch (...) {
        }
        for (std::size_t i = start; i < end; ++i) arrays.fail(i, error);
        continue;
      }
      for (std::size_t k = 0; k < replies.size(); ++k) {
        auto outcome = client::outcome_of<protocol::ContactAndMoments>(std::move(replies[k]));
        if (outcome.error) {
          arrays.fail(start + k, outcome.error);
        } else {
          arrays.set(start + k, analysis::LoadCase{protocol::contact_of(outcome.result->contact),
                                                   outcome.result->moments});
        }
      }
    }
    for (; start < count; ++start) arrays.fail(start, timeout);
  }
  return arrays.finish();
}

CaseTableObject estimate_friction_many(const Client& self, const CouplingArgument& coupling,
                                       const ArrayArgument& torque_nm,
                                       const ArrayArgument& misalignment_rad,
                                       const ArrayArgument& direction_rad,
                                       const ArrayArgument& sensor_moment_y_nm,
                                       const ArrayArgument& sensor_moment_z_nm,
                                std::size_t in_flight, const std::string& errors) {
  const protocol::CouplingRef ref = coupling_ref(remote_coupling_argument(coupling));
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad", "sensor_moment_y_nm",
                       "sensor_moment_z_nm"},
                      {torque_nm, misalignment_rad, direction_rad, sensor_moment_y_nm, sensor_moment_z_nm});
  client::Client& client = *self.client;
  return run_remote_cases(client, Calculation::kFrictionEstimate, friction_estimate_columns(),
                          in, in_flight,
                          failed_cases_argument(errors), [&](std::size_t i) {
                            const FrictionMeasurement m{in(0, i), in(1, i), in(2, i), in(3, i), in(4, i)};
                            return getter(client.call_async<Calculation::kFrictionEstimate>({ref, m}));
                          });
}

bool wait_for_service(const Client& self, double timeout_s) {
  py::gil_scoped_release release;
  return self.client->wait_for_service(
      Calculation::kToothContact, std::chrono::milliseconds(static_cast<long long>(timeout_s * 1000.0)));
}

py::dict counters(const Client& self) {
  const client::ClientCounters c = self.client->counters();
  py::dict out;
  out["sent"] = c.sent;
  out["replies"] = c.replies;
  out["resent"] = c.resent;
  out["duplicates"] = c.duplicates;
  out["foreign"] = c.foreign;
  out["timeouts"] = c.timeouts;
  return out;
}

}  // namespace

void bind_client(py::module_& m) {
  constexpr std::size_t kInFlight = 256;
  // induced_moments_many's cases go in batches (at most 16 of this client's in flight).
  constexpr std::size_t kCasesInFlight = 16384;
  py::class_<Client>(m, "Client",
                     "The calculations through gearcoupling-service over DDS (the network from "
                     "$CYCLONEDDS_URI). Same calls and results as in process; thread-safe.")
      .def(py::init([](int domain, double timeout) { return Client{make_client(domain, timeout)}; }),
           py::arg("domain") = 0, py::arg("timeout") = 5.0,
           "domain: DDS domain id [0, 230]; timeout: longest a call waits for its reply, discovery "
           "included [s].")
      .def("tooth_contact", &tooth_contact, py::arg("coupling"), py::arg("torque_nm"),
           py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(), py::arg("mu") = 0.0,
           GC_PYTHON_CONTACT_OPTION_ARGS, "gearcoupling.tooth_contact on the service.")
      .def("induced_moments", &induced_moments, py::arg("coupling"), py::arg("torque_nm"),
           py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(), py::arg("mu"),
           GC_PYTHON_CONTACT_OPTION_ARGS, "gearcoupling.induced_moments on the service.")
      .def("jam_angle", &jam_angle, py::arg("coupling"), "gearcoupling.jam_angle on the service.")
      .def("restoring_torque", &restoring_torque, py::arg("coupling"),
           "gearcoupling.restoring_torque on the service.")
      .def("estimate_friction", &estimate_friction, py::arg("coupling"), py::arg("torque_nm"),
           py::arg("misalignment_rad"), py::arg("direction_rad"), py::arg("sensor_moment_y_nm"),
           py::arg("sensor_moment_z_nm"), "gearcoupling.estimate_friction on the service.")
      .def("tooth_contact_many", &tooth_contact_many, py::arg("coupling"), py::arg("torque_nm"),
           py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(),
           GC_PYTHON_CONTACT_OPTION_ARGS, py::arg("in_flight") = kInFlight, py::arg("errors") = "raise",
           "gearcoupling.tooth_contact_many on the service, in_flight cases outstanding at once.")
      .def("induced_moments_many", &induced_moments_many, py::arg("coupling"), py::arg("torque_nm"),
           py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(), py::arg("mu"),
           GC_PYTHON_CONTACT_OPTION_ARGS, py::arg("in_flight") = kCasesInFlight,
           py::arg("errors") = "raise",
           "gearcoupling.induced_moments_many on the service: in_flight cases outstanding at once, "
           "in batches of up to 4096 cases a request.")
      .def("estimate_friction_many", &estimate_friction_many, py::arg("coupling"), py::arg("torque_nm"),
           py::arg("misalignment_rad"), py::arg("direction_rad"), py::arg("sensor_moment_y_nm"),
           py::arg("sensor_moment_z_nm"), py::kw_only(), py::arg("in_flight") = kInFlight,
           py::arg("errors") = "raise",
           "gearcoupling.estimate_friction_many on the service, in_flight cases outstanding at once.")
      .def("wait_for_service", &wait_for_service, py::arg("timeout"),
           "Waits until an instance is ready (at most timeout [s]); False if none was.")
      .def("counters", &counters, "What happened to this client's requests so far.");
}

}  // namespace gc::python
