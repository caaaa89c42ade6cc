// The fault table's shapes (fault_table_builders.hpp): some of its rows, and the tables of
// sensor placement, are the whole table's rows bit for bit, on the steady table and on the
// monitor's (fdi, whose sensor tables share the fault runs of several added channels). The
// verdict sentence (candidate_class.hpp) reads them instead of whole tables, and says the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/candidate_class.hpp"
#include "../support/loaded_circuit.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/fault_table_builders.hpp"
#include "hstmon_circuit/operating_points.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"

namespace {

namespace ct = hstmon::circuit_tools;

using hstmon_test::load_hst45;

// Row k in words exact to the bit: magnitudes, slopes, orders, directions, gain, remarks.
std::string row_text(const ct::CircuitFaultTable& t, std::size_t k) {
  const ct::CircuitFaultTable::Row& r = t.rows[k];
  std::string s = t.names[k] + (r.sensor ? " sensor" : "");
  for (int i = 0; i < ct::CircuitFaultTable::Row::kChannels; ++i) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &r.direction[i], sizeof bits);
    s += " | " + std::to_string(r.channel[i].magnitude) + " " + std::to_string(r.channel[i].slope) + " " +
         std::to_string(r.channel[i].order) + " " + std::to_string(bits);
  }
  if (k < t.gains.size()) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &t.gains[k], sizeof bits);
    s += " | gain " + std::to_string(bits);
  }
  if (k < t.remarks.size()) s += " | " + t.remarks[k];
  return s;
}

std::vector<std::string> rows_text(const ct::CircuitFaultTable& t) {
  std::vector<std::string> v;
  for (std::size_t k = 0; k < t.rows.size(); ++k) v.push_back(row_text(t, k));
  return v;
}

bool named(const std::vector<std::string>& faults, const std::string& f) {
  return std::find(faults.begin(), faults.end(), f) != faults.end();
}

// `part` holds the rows of `faults` and every sensor row of `whole`, in its order, and those
// of `faults` it lists as undetectable.
void expect_rows_of(const ct::CircuitFaultTable& whole, const ct::CircuitFaultTable& part,
                    const std::vector<std::string>& faults) {
  std::vector<std::string> rows, undetectable;
  for (std::size_t k = 0; k < whole.rows.size(); ++k) {
    if (whole.rows[k].sensor || named(faults, whole.names[k])) rows.push_back(row_text(whole, k));
  }
  for (const std::string& f : whole.undetectable) {
    if (named(faults, f)) undetectable.push_back(f);
  }
  EXPECT_EQ(rows_text(part), rows);
  EXPECT_EQ(part.undetectable, undetectable);
}

void expect_same_tables(const std::vector<std::optional<ct::CircuitFaultTable>>& each, const ct::LoadedCircuit& c,
                        const std::vector<ct::AddedSensor>& added, ct::FaultTableBuilder build) {
  ASSERT_EQ(each.size(), added.size());
  for (std::size_t k = 0; k < added.size(); ++k) {
    const ct::CircuitFaultTable direct = build(ct::with_added_sensor(c, added[k]));
    ASSERT_TRUE(each[k].has_value()) << added[k].name;
    EXPECT_EQ(rows_text(*each[k]), rows_text(direct)) << added[k].name;
    EXPECT_EQ(each[k]->undetectable, direct.undetectable) << added[k].name;
    EXPECT_EQ(each[k]->notes, direct.notes) << added[k].name;
  }
}

// fault_leak_B's final candidates (two undetectable at the nominal point), a name that is no
// fault, and a sensor row.
const std::vector<std::string> kFaults = {"R_ext_b-", "R_ip-", "R_im-", "sensor_w_m", "p_rv_b-",
                                          "Dp-",      "n_e-",  "eps-",  "no_such+"};

TEST(FaultTableShapes, SteadyRowsAreTheWholeTablesRowsAtEveryOperatingPoint) {
  const ct::LoadedCircuit c = load_hst45();
  for (const ct::OperatingPoint& op : ct::operating_points(c)) {
    ct::LoadedCircuit at = c;
    at.values.inputs = op.inputs;
    expect_rows_of(ct::circuit_fault_table(at), ct::circuit_fault_rows(at, kFaults), kFaults);
  }
}

TEST(FaultTableShapes, MonitorRowsAreTheWholeTablesRows) {
  const ct::LoadedCircuit c = load_hst45();
  expect_rows_of(hstmon::fdi::circuit_signature_table(c), hstmon::fdi::circuit_signature_rows(c, kFaults), kFaults);
}

TEST(FaultTableShapes, SensorPlacementTablesAreTheTablesWithEachSensor) {
  // hst45 measures 4 channels of 8: its 10 tries (flow meters) take 3 rounds of shared runs,
  // and the slopes its rows keep on them are checked on those runs.
  const ct::LoadedCircuit c = load_hst45();
  const std::vector<ct::AddedSensor> added = ct::added_sensors(c);
  ASSERT_GT(added.size(), 8u);
  expect_same_tables(hstmon::fdi::circuit_signature_tables_with_each(c, added), c, added,
                     hstmon::fdi::circuit_signature_table);
  expect_same_tables(ct::circuit_fault_tables_with_each(c, added), c, added, ct::circuit_fault_table);
}

TEST(FaultTableShapes, VerdictOnTheCallersTableSaysTheSame) {
  const ct::LoadedCircuit c = load_hst45();
  const ct::CircuitFaultTable table = ct::circuit_fault_table(c);
  for (const std::vector<std::string>& cands :
       {std::vector<std::string>{"R_ip-", "R_im-"}, std::vector<std::string>{"R_ext_a-", "R_ip-", "Dp-"},
        std::vector<std::string>(kFaults.begin(), kFaults.end() - 1)}) {
    const ct::CandidateClass built = ct::candidate_class(c, cands);
    const ct::CandidateClass given = ct::candidate_class(c, cands, ct::steady_fault_tables(), &table);
    EXPECT_EQ(given.sentence, built.sentence);
    EXPECT_EQ(given.groups_split, built.groups_split);
  }
}

}  // namespace
