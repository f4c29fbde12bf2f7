#include "job_store.h"
#include <algorithm>
#include <stdexcept>

namespace photon::server {

namespace {

const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS jobs (
    seq INTEGER PRIMARY KEY AUTOINCREMENT,
    id TEXT NOT NULL UNIQUE,
    status TEXT NOT NULL,
    priority INTEGER NOT NULL,
    created_at TEXT NOT NULL,
    started_at TEXT,
    finished_at TEXT,
    passes INTEGER NOT NULL,
    photons_per_pass INTEGER NOT NULL,
    seed INTEGER NOT NULL,
    integrator TEXT NOT NULL,
    width INTEGER NOT NULL,
    height INTEGER NOT NULL,
    pass INTEGER NOT NULL DEFAULT 0,
    photons_traced INTEGER NOT NULL DEFAULT 0,
    mean_radius REAL NOT NULL DEFAULT 0,
    elapsed_seconds REAL NOT NULL DEFAULT 0,
    eta_seconds REAL NOT NULL DEFAULT 0,
    error TEXT
);
)sql";

// Version 2: the submitting client's address (for per-client limits) and idempotency keys.
// Databases of version 1 are migrated in place when opened; their jobs keep a NULL client.
const char* kMigrateTo2 = R"sql(
BEGIN IMMEDIATE;
ALTER TABLE jobs ADD COLUMN client TEXT;
CREATE TABLE IF NOT EXISTS idempotency_keys (
    key TEXT PRIMARY KEY,
    request_hash TEXT NOT NULL,
    job_id TEXT NOT NULL,
    created_unix INTEGER NOT NULL
);
CREATE INDEX IF NOT EXISTS idempotency_keys_by_age ON idempotency_keys (created_unix);
PRAGMA user_version = 2;
COMMIT;
)sql";
// Version 3: each job's upload size (the per-client disk limit), its warnings and labels
// (one a line), its name and the time of its last change. Older jobs count 0 bytes, have no
// warnings, labels or name, and were last changed when they were created.
const char* kMigrateTo3 = R"sql(
BEGIN IMMEDIATE;
ALTER TABLE jobs ADD COLUMN upload_bytes INTEGER NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN warnings TEXT;
ALTER TABLE jobs ADD COLUMN name TEXT;
ALTER TABLE jobs ADD COLUMN labels TEXT;
ALTER TABLE jobs ADD COLUMN updated_at TEXT;
UPDATE jobs SET updated_at = COALESCE(finished_at, started_at, created_at);
PRAGMA user_version = 3;
COMMIT;
)sql";
// Versions 4 on each add one column to the jobs: what the job's record says of the jobs
// before it (NULL, 0).
std::string addColumn(int version, const std::string& column) {
    return "BEGIN IMMEDIATE;\nALTER TABLE jobs ADD COLUMN " + column + ";\nPRAGMA user_version = " +
           std::to_string(version) + ";\nCOMMIT;\n";
}
// Version 4: the camera an imported glTF scene was asked to render from (NULL: its first,
// and every job before).
const std::string kMigrateTo4 = addColumn(4, "camera TEXT");
// Version 5: whether the job's scene asks for the denoiser (0 for every job before, which is
// only what the record says: their images are as rendered).
const std::string kMigrateTo5 = addColumn(5, "denoise INTEGER NOT NULL DEFAULT 0");
// Version 6: the relative error the render stops at (0, none, for every job before).
const std::string kMigrateTo6 = addColumn(6, "target_error REAL NOT NULL DEFAULT 0");
// Version 7: whether an imported pbrt scene's import left out what photon cannot render (0 for
// every job before: they were imported strictly).
const std::string kMigrateTo7 = addColumn(7, "lenient INTEGER NOT NULL DEFAULT 0");
constexpr int64_t kSchemaVersion = 7;

const char* kInsert =
    "INSERT INTO jobs (id, status, priority, created_at, passes, photons_per_pass, seed, integrator, width, height,"
    " client, upload_bytes, warnings, name, labels, updated_at, camera, denoise, target_error, lenient)"
    " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, ?19, ?20)";

const char* kUpdate =
    "UPDATE jobs SET status = ?2, started_at = ?3, finished_at = ?4, pass = ?5, photons_traced = ?6,"
    " mean_radius = ?7, elapsed_seconds = ?8, eta_seconds = ?9, error = ?10, updated_at = ?11,"
    " priority = ?12, passes = ?13, target_error = ?14 WHERE id = ?1";

const char* kRemove = "DELETE FROM jobs WHERE id = ?1";
const char* kRemoveKeysOf = "DELETE FROM idempotency_keys WHERE job_id = ?1";
const char* kForgetKeys = "DELETE FROM idempotency_keys WHERE created_unix < ?1";
const char* kInsertKey =
    "INSERT OR REPLACE INTO idempotency_keys (key, request_hash, job_id, created_unix) VALUES (?1, ?2, ?3, ?4)";
const char* kFindKey =
    "SELECT request_hash, job_id, created_unix FROM idempotency_keys WHERE key = ?1 AND created_unix >= ?2";

const char* kSelectAll =
    "SELECT seq, id, status, priority, created_at, started_at, finished_at, passes, photons_per_pass, seed,"
    " integrator, width, height, pass, photons_traced, mean_radius, elapsed_seconds, eta_seconds, error, client,"
    " upload_bytes, warnings, name, labels, updated_at, camera, denoise, target_error, lenient FROM jobs ORDER BY seq";

int64_t schemaVersion(sql::Database& db) {
    sql::Statement version = db.prepare("PRAGMA user_version");
    return version.step() ? version.integer(0) : 0;
}

void migrate(sql::Database& db, const char* script) {
    try {
        db.exec(script);
    } catch (...) {
        try {
            db.exec("ROLLBACK");
        } catch (...) {  // the transaction never began
        }
        throw;
    }
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += (text.empty() ? "" : "\n") + line;
    return text;
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    for (size_t start = 0; start < text.size();) {
        size_t end = std::min(text.find('\n', start), text.size());
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

// Opening creates or migrates the schema, so it must run before the statements are prepared.
sql::Database& withSchema(sql::Database& db) {
    db.exec(kSchema);
    int64_t version = schemaVersion(db);
    if (version > kSchemaVersion)
        throw std::runtime_error("the job database is of a newer version (" + std::to_string(version) +
                                 ") than this server knows (" + std::to_string(kSchemaVersion) + ")");
    if (version < 2) migrate(db, kMigrateTo2);
    if (version < 3) migrate(db, kMigrateTo3);
    if (version < 4) migrate(db, kMigrateTo4.c_str());
    if (version < 5) migrate(db, kMigrateTo5.c_str());
    if (version < 6) migrate(db, kMigrateTo6.c_str());
    if (version < 7) migrate(db, kMigrateTo7.c_str());
    return db;
}

// Runs fn inside one transaction: all of its writes land, or none.
template <typename Fn>
void inTransaction(sql::Database& db, Fn&& fn) {
    db.exec("BEGIN IMMEDIATE");
    try {
        fn();
        db.exec("COMMIT");
    } catch (...) {
        try {
            db.exec("ROLLBACK");
        } catch (...) {
        }
        throw;
    }
}

JobRecord readRow(const sql::Statement& s) {
    JobRecord job;
    job.seq = s.integer(0);
    job.id = s.text(1);
    // An unknown status can only come from a newer server version; treat it as failed.
    job.status = parseJobStatus(s.text(2)).value_or(JobStatus::Failed);
    job.priority = int(s.integer(3));
    job.createdAt = s.text(4);
    job.startedAt = s.text(5);
    job.finishedAt = s.text(6);
    job.settings.passes = int(s.integer(7));
    job.settings.photonsPerPass = s.integer(8);
    job.settings.seed = uint64_t(s.integer(9));  // SQLite integers are signed: stored bit for bit
    job.settings.integrator = s.text(10);
    job.settings.width = int(s.integer(11));
    job.settings.height = int(s.integer(12));
    job.progress.pass = int(s.integer(13));
    job.progress.photonsTraced = s.integer(14);
    job.progress.meanRadius = s.real(15);
    job.progress.elapsedSeconds = s.real(16);
    job.progress.etaSeconds = s.real(17);
    job.error = s.text(18);
    job.client = s.text(19);
    job.uploadBytes = s.integer(20);
    job.warnings = splitLines(s.text(21));
    job.name = s.text(22);
    job.labels = splitLines(s.text(23));
    job.updatedAt = s.text(24);
    job.settings.camera = s.text(25);
    job.settings.denoise = s.integer(26) != 0;
    job.settings.targetError = s.real(27);
    job.settings.lenient = s.integer(28) != 0;
    return job;
}

}  // namespace

JobStore::JobStore(const std::filesystem::path& databaseFile)
    : db_(databaseFile),
      insert_(withSchema(db_).prepare(kInsert)),
      update_(db_.prepare(kUpdate)),
      remove_(db_.prepare(kRemove)),
      selectAll_(db_.prepare(kSelectAll)),
      removeKeysOf_(db_.prepare(kRemoveKeysOf)),
      forgetKeys_(db_.prepare(kForgetKeys)),
      insertKey_(db_.prepare(kInsertKey)),
      findKey_(db_.prepare(kFindKey)) {}

int64_t JobStore::insert(const JobRecord& job, const std::optional<IdempotencyEntry>& key) {
    std::lock_guard lock(mutex_);
    int64_t seq = 0;
    inTransaction(db_, [&] {
        insert_.reset();
        insert_.bind(1, job.id).bind(2, std::string(toString(job.status))).bind(3, int64_t(job.priority));
        insert_.bind(4, job.createdAt).bind(5, int64_t(job.settings.passes)).bind(6, job.settings.photonsPerPass);
        insert_.bind(7, int64_t(job.settings.seed)).bind(8, job.settings.integrator);
        insert_.bind(9, int64_t(job.settings.width)).bind(10, int64_t(job.settings.height));
        insert_.bindTextOrNull(11, job.client).bind(12, job.uploadBytes).bindTextOrNull(13, joinLines(job.warnings));
        insert_.bindTextOrNull(14, job.name).bindTextOrNull(15, joinLines(job.labels));
        insert_.bindTextOrNull(16, job.updatedAt).bindTextOrNull(17, job.settings.camera);
        insert_.bind(18, int64_t(job.settings.denoise)).bind(19, job.settings.targetError);
        insert_.bind(20, int64_t(job.settings.lenient));
        insert_.run();
        seq = db_.lastInsertRowId();
        if (!key) return;
        forgetKeys_.reset();
        forgetKeys_.bind(1, key->createdUnix - kIdempotencyKeySeconds).run();
        insertKey_.reset();
        insertKey_.bind(1, key->key).bind(2, key->requestHash).bind(3, job.id).bind(4, key->createdUnix);
        insertKey_.run();
    });
    return seq;
}

std::optional<IdempotencyEntry> JobStore::findKey(const std::string& key, int64_t nowUnix) {
    std::lock_guard lock(mutex_);
    findKey_.reset();
    findKey_.bind(1, key).bind(2, nowUnix - kIdempotencyKeySeconds);
    std::optional<IdempotencyEntry> entry;
    if (findKey_.step()) entry = IdempotencyEntry{key, findKey_.text(0), findKey_.text(1), findKey_.integer(2)};
    findKey_.reset();
    return entry;
}

void JobStore::update(const JobRecord& job) {
    std::lock_guard lock(mutex_);
    update_.reset();
    update_.bind(1, job.id).bind(2, std::string(toString(job.status)));
    update_.bindTextOrNull(3, job.startedAt).bindTextOrNull(4, job.finishedAt);
    update_.bind(5, int64_t(job.progress.pass)).bind(6, job.progress.photonsTraced);
    update_.bind(7, job.progress.meanRadius).bind(8, job.progress.elapsedSeconds);
    update_.bind(9, job.progress.etaSeconds).bindTextOrNull(10, job.error).bindTextOrNull(11, job.updatedAt);
    update_.bind(12, int64_t(job.priority)).bind(13, int64_t(job.settings.passes)).bind(14, job.settings.targetError);
    update_.run();
}

void JobStore::remove(const std::string& id) {
    std::lock_guard lock(mutex_);
    inTransaction(db_, [&] {
        remove_.reset();
        remove_.bind(1, id).run();
        removeKeysOf_.reset();
        removeKeysOf_.bind(1, id).run();
    });
}

std::vector<JobRecord> JobStore::loadAll() {
    std::lock_guard lock(mutex_);
    std::vector<JobRecord> jobs;
    selectAll_.reset();
    while (selectAll_.step()) jobs.push_back(readRow(selectAll_));
    selectAll_.reset();
    return jobs;
}

}  // namespace photon::server
