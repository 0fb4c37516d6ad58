// Batch mode (docs/cli.md "Batch mode"): one problem per CSV row through the subcommand's own
// options, JSON Lines or CSV rows, invalid rows reported without ending the batch, exit 2 / 3 at
// the end.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

using Json = nlohmann::ordered_json;

/// Writes `text` to a file of this test's own and returns its path.
std::string batch_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("lac_cli_batch_test_" + std::to_string(::getpid()) + "_" + name + ".csv");
  std::ofstream(path) << text;
  return path.string();
}

std::vector<Json> lines(const std::string& out) {
  std::vector<Json> rows;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) rows.push_back(Json::parse(line));
  return rows;
}

TEST(CliBatch, RowsInvalidRowsAndDefaultsFromTheCommandLine) {
  const std::string file = batch_file("g1",
                                      "points,alpha\n"
                                      "\"0,0 1,0 2,1\",-1\n"
                                      "\"0,0 1,0 2,1\",5\n"      // no_solution
                                      "\"0,0 1,0 2,1\",abc\n"    // invalid: alpha
                                      "\"0,0 1,0\",1\r\n"        // invalid: points (and a CRLF line end)
                                      "\"0,0 1,0 2,1\",\n"       // alpha from the command line
                                      "# a comment\n"
                                      "\n"
                                      " \"0,0 1,0 2,1\" , 2 \n");
  // --winding 0: the alpha = 5 row has no curve turning at most pi (it has one winding round).
  const test::CliRun r = test::run_lac_stdout("g1 --alpha 2 --winding 0 --batch " + file);
  EXPECT_EQ(r.status, 2) << r.out;  // invalid rows: 2 at the end, every row printed
  const std::vector<Json> rows = lines(r.out);
  ASSERT_EQ(rows.size(), 6u) << r.out;
  for (size_t k = 0; k < rows.size(); ++k) EXPECT_EQ(rows[k]["row"], k + 1) << rows[k].dump();
  EXPECT_EQ(rows[0]["status"], "ok");
  EXPECT_EQ(rows[1]["status"], "no_solution");
  EXPECT_TRUE(rows[1]["length"].is_null());
  EXPECT_EQ(rows[2]["status"], "invalid_input");
  EXPECT_EQ(rows[2]["message"].get<std::string>().rfind("alpha: ", 0), 0u) << rows[2].dump();
  EXPECT_EQ(rows[3]["status"], "invalid_input");
  EXPECT_EQ(rows[3]["message"].get<std::string>().rfind("points: ", 0), 0u) << rows[3].dump();
  EXPECT_EQ(rows[4]["status"], "ok");
  EXPECT_EQ(rows[4]["segments"][0]["alpha"], 2.0);  // --alpha 2 from the command line
  EXPECT_EQ(rows[5]["length"], rows[4]["length"]);  // blanks around fields
  // The same problem alone gives the same report.
  const Json one = Json::parse(test::run_lac_stdout("g1 --points '0,0 1,0 2,1' --alpha -1").out);
  EXPECT_EQ(rows[0]["length"], one["length"]);
  EXPECT_EQ(rows[0]["segments"], one["segments"]);
}

TEST(CliBatch, ExitStatusThreeWithoutInvalidRowsAndZeroWhenAllAreUsable) {
  const std::string mixed = batch_file("mixed", "alpha\n-1\n5\n");
  EXPECT_EQ(test::run_lac_stdout("g1 --points '0,0 1,0 2,1' --winding 0 --batch " + mixed).status, 3);
  const std::string good = batch_file("good", "alpha\n-1\n2\n");
  EXPECT_EQ(test::run_lac_stdout("g1 --points '0,0 1,0 2,1' --batch " + good).status, 0);
  // From stdin.
  const test::CliRun in = test::run_lac_stdout("g1 --points '0,0 1,0 2,1' --batch - < " + good);
  EXPECT_EQ(in.status, 0);
  EXPECT_EQ(lines(in.out).size(), 2u);
}

TEST(CliBatch, CsvRowsWithTheSummaryKeys) {
  const std::string file = batch_file("csv", "points,alpha\n\"0,0 1,0\",1\n\"0,0 1,0 2,1\",-1\n\"0,0 1,0 2,1\",5\n");
  const test::CliRun r = test::run_lac_stdout("g1 --winding 0 --batch " + file + " --format csv");
  EXPECT_EQ(r.status, 2) << r.out;
  std::istringstream in(r.out);
  std::string header, row1, row2, row3;
  std::getline(in, header), std::getline(in, row1), std::getline(in, row2), std::getline(in, row3);
  EXPECT_EQ(header.rfind("row,status,message,length,kappa0,kappa1,iterations,evaluations,seconds,solver,integrator,", 0), 0u)
      << r.out;
  EXPECT_EQ(row1.rfind("1,invalid_input,\"points: ", 0), 0u) << r.out;  // before the first result: kept, then printed
  EXPECT_EQ(row2.rfind("2,ok,,", 0), 0u) << r.out;
  EXPECT_EQ(row3.rfind("3,no_solution,", 0), 0u) << r.out;
  const auto commas = [](const std::string& s) { return std::count(s.begin(), s.end(), ','); };
  EXPECT_EQ(commas(row2), commas(header));
}

TEST(CliBatch, EveryConstructionAndEval) {
  struct Case {
    std::string command, header, row;
  };
  const Case cases[] = {
      {"eval", "alpha,lambda,theta", "2,1,1"},
      {"eval --degrees", "alpha,lambda,theta", "2,1,57.295779513082323"},
      {"eval", "alpha,lambda,s,samples", "-1,1,0.8,3"},
      {"quadratic", "alpha,gamma,lambda,samples", "1,1,1,0"},
      {"g1", "points,alpha,solver,integrator", "\"0,0 1,0 2,1\",-1,bisection,rk45"},
      {"compound", "points,alpha0,alpha1,r", "\"3,2 1.5,0.2 0.5,0.9\",2,0.5,0.3"},
      {"scurve", "points,alpha", "\"0,0 1,0 2,1 3,1\",-1"},
      {"g2", "p0,theta0,kappa0,p1,theta1,kappa1,alpha,no-fallback", "\"0,0\",0.6,0.5,\"4,0\",-0.6,-0.3,-0.5,true"},
      {"space", "p0,v0,p1,v1,alpha,beta",
       "\"0,0,0\",\"1,0,0\",\"0.36235775447667362,0.93203908596722629,0\","
       "\"-0.4838825660252134,0.8293701183329452,0.279289937364832\",-1,-1"},
  };
  for (const Case& c : cases) {
    const std::string file = batch_file("every", c.header + "\n" + c.row + "\n" + c.row + "\n");
    const test::CliRun r = test::run_lac_stdout(c.command + " --batch " + file);
    EXPECT_EQ(r.status, 0) << c.command << "\n" << r.out;
    const std::vector<Json> rows = lines(r.out);
    ASSERT_EQ(rows.size(), 2u) << r.out;
    EXPECT_EQ(rows[1]["row"], 2);
    EXPECT_EQ(rows[1]["status"], "ok") << rows[1].dump();
    EXPECT_EQ(rows[0]["length"], rows[1]["length"]);
  }
  const Json eval = lines(test::run_lac_stdout("eval --batch " + batch_file("eval", "alpha,lambda,theta\n2,1,1\n")).out)[0];
  EXPECT_DOUBLE_EQ(eval["point"]["s"].get<double>(), 1.5);
}

TEST(CliBatch, BadHeaderOrFileIsOneErrorLine) {
  const std::pair<std::string, std::string> cases[] = {
      {"g1 --batch " + batch_file("unknown", "points,alfa\n\"0,0 1,0 2,1\",1\n"), "alfa"},
      {"g1 --batch " + batch_file("typo", "pionts,alpha\n\"0,0 1,0 2,1\",1\n"),
       "column 'pionts' names no option of this command; did you mean 'points'?"},
      {"g1 --batch " + batch_file("unknown_far", "points,xyzzy\n\"0,0 1,0 2,1\",1\n"), "column 'xyzzy' names no option"},
      // The same option twice is an error naming both columns, not a silent choice of one.
      {"g1 --batch " + batch_file("duplicate", "alpha,points,alpha\n1,\"0,0 1,0 2,1\",2\n"),
       "column 'alpha' (column 3) repeats the option of column 1"},
      {"g1 --batch " + batch_file("format", "points,format\n\"0,0 1,0 2,1\",csv\n"), "format"},
      {"g1 --batch /nonexistent/rows.csv", "cannot open"},
      {"g1 --batch " + batch_file("svg", "alpha\n1\n") + " --format svg", "svg"},
  };
  for (const auto& [args, text] : cases) {
    const test::CliRun r = test::run_lac_stderr(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_EQ(r.out.rfind("lac g1: ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find(text), std::string::npos) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  }
}

TEST(CliBatch, RowWithTheWrongNumberOfFields) {
  const std::string file = batch_file("fields", "points,alpha\n\"0,0 1,0 2,1\"\n\"0,0 1,0 2,1\",1,2\n");
  const test::CliRun r = test::run_lac_stdout("g1 --batch " + file);
  EXPECT_EQ(r.status, 2);
  for (const Json& row : lines(r.out)) {
    EXPECT_EQ(row["status"], "invalid_input");
    EXPECT_NE(row["message"].get<std::string>().find("fields"), std::string::npos) << row.dump();
  }
}

TEST(CliBatch, HeaderAfterAByteOrderMark) {
  // Spreadsheets write UTF-8 CSV with a byte order mark before the first column name.
  for (const std::string& header : {std::string("alpha,points"), std::string("\"alpha\",points")}) {
    const std::string file = batch_file("bom", "\xEF\xBB\xBF" + header + "\n-1,\"0,0 1,0 2,1\"\n");
    const test::CliRun r = test::run_lac_stdout("g1 --batch " + file);
    EXPECT_EQ(r.status, 0) << header << "\n" << r.out;
    const std::vector<Json> rows = lines(r.out);
    ASSERT_EQ(rows.size(), 1u) << r.out;
    EXPECT_EQ(rows[0]["status"], "ok") << r.out;
  }
}

TEST(CliBatch, BadCellIsEchoedShortAndPrintable) {
  // A long bad cell is cut to 60 characters and "…"; a NUL byte is written as \x00, the rest of
  // the message kept.
  const std::string long_cell(100000, 'x');
  const std::string file = batch_file("badcell", "points,alpha\n\"0,0 1,0 2,1\"," + long_cell + "\n\"0,0 1,0 2,1\",\"1" +
                                                     std::string(1, '\0') + "5\"\n\"0,0 1,0 2,1\",-1\n");
  const test::CliRun r = test::run_lac_stdout("g1 --batch " + file);
  EXPECT_EQ(r.status, 2) << r.out.substr(0, 2000);
  const std::vector<Json> rows = lines(r.out);
  ASSERT_EQ(rows.size(), 3u) << r.out.substr(0, 2000);
  const std::string too_long = rows[0]["message"];
  EXPECT_EQ(rows[0]["status"], "invalid_input");
  EXPECT_LT(too_long.size(), 1200u) << too_long.substr(0, 2000);
  EXPECT_EQ(too_long.rfind("alpha: '" + std::string(60, 'x') + "…'", 0), 0u) << too_long.substr(0, 2000);
  const std::string nul = rows[1]["message"];
  EXPECT_EQ(rows[1]["status"], "invalid_input");
  EXPECT_EQ(nul.rfind("alpha: '1\\x005': a NUL byte (at character 2) is not text", 0), 0u) << nul;
  EXPECT_EQ(rows[2]["status"], "ok");
  // The CLI's own parsers echo a value as short.
  const std::string points = "\"0,0 1,0 2," + std::string(5000, '1') + "z\"";
  const std::string bad_points = batch_file("badpoints", "points,alpha\n" + points + ",-1\n");
  const std::vector<Json> p = lines(test::run_lac_stdout("g1 --batch " + bad_points).out);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_LT(p[0]["message"].get<std::string>().size(), 400u) << p[0].dump();
  EXPECT_NE(p[0]["message"].get<std::string>().find("…"), std::string::npos) << p[0].dump();
}

}  // namespace
}  // namespace lac
