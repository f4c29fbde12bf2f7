// A minimal RAII face over the sqlite3 C API: a connection and prepared statements with
// positional binding. Values only ever reach SQL through bind(), never through the text.
#pragma once
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace photon::server::sql {

// Every failure, with SQLite's extended result code so callers can tell a full disk from a bug.
class Error : public std::runtime_error {
public:
    Error(const std::string& message, int code) : std::runtime_error(message), code_(code) {}
    int code() const { return code_; }
    bool diskFull() const;  // SQLITE_FULL
    bool readOnly() const;  // SQLITE_READONLY: the file or its file system cannot be written

private:
    int code_;
};

class Statement {
public:
    Statement(sqlite3* db, const char* sql);
    ~Statement();
    Statement(Statement&& other) noexcept;
    Statement& operator=(Statement&&) = delete;
    Statement(const Statement&) = delete;

    // Parameters are numbered from 1, as in SQLite.
    Statement& bind(int index, int64_t value);
    Statement& bind(int index, double value);
    Statement& bind(int index, const std::string& value);
    // Empty strings are stored as NULL: for optional text such as timestamps.
    Statement& bindTextOrNull(int index, const std::string& value);

    // Runs one step: true while rows come, false when done. Throws on errors.
    bool step();
    // Runs a statement that returns no rows, then resets it for the next use.
    void run();
    // Clears bindings and rewinds; call before binding a reused statement.
    void reset();

    int64_t integer(int column) const;
    double real(int column) const;
    std::string text(int column) const;  // NULL reads as ""

private:
    sqlite3* db_;
    sqlite3_stmt* stmt_ = nullptr;
};

class Database {
public:
    // Opens (creating if needed) the file in WAL mode: readers do not block the writer.
    explicit Database(const std::filesystem::path& file);
    ~Database();
    Database(const Database&) = delete;
    Database& operator=(const Database&) = delete;

    // For fixed SQL text only (schema, pragmas): never pass client data here.
    void exec(const char* sql);
    Statement prepare(const char* sql) { return Statement(db_, sql); }
    int64_t lastInsertRowId() const;

private:
    sqlite3* db_ = nullptr;
};

}  // namespace photon::server::sql
