#pragma once
// Reads CSV records for batch mode (cli/batch.hpp): fields separated by commas; a field in double
// quotes may hold commas, spaces, newlines and doubled quotes ("0,0 1,0 2,1"); unquoted fields
// are trimmed of spaces and tabs; CRLF line ends are accepted. Blank lines and lines starting
// with '#' are skipped.
#include <istream>
#include <string>
#include <vector>

namespace lac::cli {

/// The next record's fields into `fields`; false at the end of the input. InputError "batch" for
/// a quoted field that is not closed. `first`: this is the first record of the input, which may
/// begin with a UTF-8 byte order mark (as spreadsheets write it): the mark is skipped.
bool read_csv_record(std::istream& in, std::vector<std::string>& fields, bool first = false);

}  // namespace lac::cli
