#pragma once
/// Waiting for the window in gtest tests. Qt's QTRY_VERIFY and QTRY_COMPARE report a failure to
/// QTest's own log and return from the test body, which gtest then counts as passed: a wait that
/// never came true would pass silently. These wait the same way (handling events until the
/// condition holds or the time is up) and fail the gtest test when it does not hold.

#include <QTest>

#include <gtest/gtest.h>

/// Waits up to `timeoutMs` for `condition`; a fatal gtest failure naming it when it never holds.
#define MARBLER_WAIT(condition, timeoutMs)                                                                   \
    ASSERT_TRUE(QTest::qWaitFor([&]() -> bool { return bool(condition); }, timeoutMs))                       \
        << "waited " << (timeoutMs) << " ms for: " #condition

/// Waits up to `timeoutMs` for `actual == expected`, then asserts it (printing both values).
#define MARBLER_WAIT_EQ(actual, expected, timeoutMs)                                                         \
    do {                                                                                                     \
        (void)QTest::qWaitFor([&]() -> bool { return (actual) == (expected); }, timeoutMs);                  \
        ASSERT_EQ(actual, expected) << "after waiting " << (timeoutMs) << " ms";                             \
    } while (false)

// Qt's waits would pass silently under gtest (see above): using one is a compile error here.
#undef QTRY_VERIFY
#undef QTRY_VERIFY_WITH_TIMEOUT
#undef QTRY_COMPARE
#undef QTRY_COMPARE_WITH_TIMEOUT
#define QTRY_VERIFY(...) static_assert(false, "use MARBLER_WAIT: QTRY_VERIFY passes silently under gtest")
#define QTRY_VERIFY_WITH_TIMEOUT(...) static_assert(false, "use MARBLER_WAIT")
#define QTRY_COMPARE(...)                                                                                    \
    static_assert(false, "use MARBLER_WAIT_EQ: QTRY_COMPARE passes silently under gtest")
#define QTRY_COMPARE_WITH_TIMEOUT(...) static_assert(false, "use MARBLER_WAIT_EQ")
