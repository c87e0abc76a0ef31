/* Karma 1.2's collision error reporting: McdError / McdCoreError through the coded message hook,
 * the error numbers of McdCoreErrorList.h (also as 1.2's ERR X-macro), the McdCheck.h macros as real
 * checks, and McdProfileStart/End on Me's global profiler. */
#include "karma_test.h"

#include <string.h>

#include <karma/McdCheck.h>
#include <karma/McdMessage.h>
#include <karma/McdProfile.h>
#include <karma/McdSphere.h>

/* 1.2's own way of reading the list: an X-macro over ERR(name, type, text). */
#define ERR(name, type, text) name
static const int numbersAsErr[] = {
#include <karma/McdCoreErrorList.h>
};
#undef ERR

static void error_list_numbers(void **state)
{
    (void)state;
    size_t n = sizeof numbersAsErr / sizeof numbersAsErr[0];
    assert_int_equal(n, (size_t)kMcdMAXErrDefined + 1);
    for (size_t i = 0; i < n; i++)
        assert_int_equal(numbersAsErr[i], (int)i);
    assert_int_equal(kMcdErrorNum_GenericFatal, 0);
    /* the library's table has one entry per number, in order, ended by kMcdMAXErrDefined */
    for (int i = 0; i <= kMcdMAXErrDefined; i++)
        assert_int_equal(gMcdCoreErrorList[i].m_errNum, i);
    assert_int_equal(gMcdCoreErrorList[kMcdErrorNum_SpaceNotChanging].m_errorLevel, kMcdErrorTypeWarning);
}

/* A core error with a corresponding code is reported with it, in the given function's name; the
 * description and the message make the text. */
static void core_error_uses_our_codes(void **state)
{
    (void)state;
    karma_capture_messages();
    assert_reports(ME_ERR_BAD_STATE, McdCoreError(kMcdErrorNum_SpaceNotChanging, "MyInsert", "MyFn", __FILE__, __LINE__));
    assert_string_equal(karma_last_function(), "MyFn");
    assert_non_null(strstr(karma_last_text(), "MyInsert"));
    assert_reports(ME_ERR_MCD_NO_INTERACTION, McdCoreError(kMcdErrorNum_NoIntersectionFn, "", "f", __FILE__, __LINE__));
    assert_reports(ME_ERR_INVALID_HANDLE, McdCoreError(kMcdErrorNum_InvalidPtr_CM, "", "f", __FILE__, __LINE__));
    assert_reports(ME_ERR_POOL_FULL, McdCoreError(kMcdErrorNum_Mem_SpaceModelPairPool, "", "f", __FILE__, __LINE__));
    /* no code of ours: a warning through MeWarning (ME_ERR_USER_MESSAGE), and fatal does not abort */
    unsigned long warnings = karma_warning_count();
    McdCoreError(kMcdErrorNum_GenericFatal, "custom text", "f", __FILE__, __LINE__);
    assert_int_equal(karma_warning_count() - warnings, 1);
    assert_int_equal(karma_last_code(), ME_ERR_USER_MESSAGE);
    assert_non_null(strstr(karma_last_text(), "custom text"));
    /* an entry with count 0 is silent */
    MeI16 saved = gMcdCoreErrorList[kMcdErrorNum_InvalidPtr_TM].m_errorCount;
    gMcdCoreErrorList[kMcdErrorNum_InvalidPtr_TM].m_errorCount = 0;
    unsigned long before = MeMessageGetCount(ME_ERR_NULL_ARGUMENT);
    McdCoreError(kMcdErrorNum_InvalidPtr_TM, "", "f", __FILE__, __LINE__);
    assert_int_equal(MeMessageGetCount(ME_ERR_NULL_ARGUMENT), before);
    gMcdCoreErrorList[kMcdErrorNum_InvalidPtr_TM].m_errorCount = saved;
    assert_reports(ME_ERR_NULL_ARGUMENT, McdCoreError(kMcdErrorNum_InvalidPtr_TM, "", "f", __FILE__, __LINE__));
}

/* An application's own list: its types choose MeWarning or MeInfo. */
enum { myErrorA, myErrorB, myEnd = kMcdMAXErrDefined };
static McdErrorDescription myList[] = {
    {myErrorA, kMcdErrorTypeWarning, 5, "A went wrong: "},
    {myErrorB, kMcdErrorTypeInfo, 5, "B happened: "},
    {myEnd, kMcdErrorTypeFatal, 5, "end"},
};

static void application_error_list(void **state)
{
    (void)state;
    karma_capture_messages();
    unsigned long warnings = karma_warning_count();
    McdError(myList, myErrorA, "details", "appFn", __FILE__, __LINE__);
    assert_int_equal(karma_warning_count() - warnings, 1);
    assert_non_null(strstr(karma_last_text(), "A went wrong: details"));
    MeSetMessageLevel(ME_LEVEL_DEBUG);
    unsigned long all = MeMessageGetCount(ME_ERR_USER_MESSAGE);
    McdError(myList, myErrorB, "x", "appFn", __FILE__, __LINE__);
    assert_int_equal(karma_warning_count() - warnings, 1); /* info: no new warning */
    assert_int_equal(MeMessageGetCount(ME_ERR_USER_MESSAGE) - all, 1);
    MeSetMessageLevel(ME_LEVEL_WARNING);
    assert_reports(ME_ERR_NULL_ARGUMENT, McdError(NULL, 0, "", "f", __FILE__, __LINE__));
}

/* The check macros report a bad model, space, geometry, pair or result, and stay quiet on good ones. */
static void check_macros(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 4, 0, 1);
    McdGeometryID g = McdSphereCreate(fw, 1);
    McdModelID m = McdModelCreate(g), dead = McdModelCreate(g);
    McdModelDestroy(dead);
    unsigned long warnings = karma_warning_count();
    MCD_CHECKMODEL(m, "fn");
    MCD_CHECKGEOMETRY(g, "fn");
    MCD_CHECK_NULLPTR(g, "McdGeometry", "fn");
    MCD_ASSERT(1 + 1 == 2, "fn");
    MCD_INTERACTIONTABLE_CHECKBOUNDS(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeBox, "fn");
    assert_int_equal(karma_warning_count(), warnings);
    assert_reports(ME_ERR_INVALID_HANDLE, MCD_CHECKMODEL(dead, "fn"));
    assert_string_equal(karma_last_function(), "fn");
    assert_reports(ME_ERR_INVALID_HANDLE, MCD_CHECKSPACE(NULL, "fn"));
    assert_reports(ME_ERR_NULL_ARGUMENT, MCD_CHECK_NULLPTR(NULL, "McdGeometry", "fn"));
    assert_reports(ME_ERR_OUT_OF_MEMORY, MCDCHECK_ALLOC(NULL, "McdModel", "fn"));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MCD_INTERACTIONTABLE_CHECKBOUNDS(fw, 0, 9999, "fn"));
    McdModelPair pair;
    memset(&pair, 0, sizeof pair);
    pair.model1 = m;
    pair.model2 = dead;
    assert_reports(ME_ERR_INVALID_HANDLE, MCD_CHECKMODELPAIR(&pair, "fn"));
    McdIntersectResult r;
    memset(&r, 0, sizeof r);
    assert_reports(ME_ERR_NULL_ARGUMENT, MCD_CHECKINTERSECTRESULT(&r, "fn"));
    warnings = karma_warning_count();
    MCD_ASSERT(1 + 1 == 3, "fn");
    assert_int_equal(karma_warning_count() - warnings, 1);
    assert_non_null(strstr(karma_last_text(), "1 + 1 == 3"));
    if (m) /* one statement each: usable as the body of an if */
        MCD_CHECKMODEL(m, "fn");
    else
        MCD_CHECKMODEL(m, "fn");
    McdModelDestroy(m);
    McdGeometryDestroy(g);
    McdTerm(fw);
}

/* McdProfileStart/End time a section of Me's global profiler. */
static void profile_sections(void **state)
{
    (void)state;
    volatile double sink = 0;
    MeProfileStartFrame();
    McdProfileStart("McdTestSection");
    for (int i = 0; i < 200000; i++)
        sink += i * 0.5;
    McdProfileEnd("McdTestSection");
    MeProfileEndFrame();
    assert_true(sink > 0);
    assert_true(MeProfileGetSectionTime("McdTestSection") > 0);
    assert_true(MeProfileGetSectionTime("McdNeverStarted") == 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(error_list_numbers),   cmocka_unit_test(core_error_uses_our_codes),
        cmocka_unit_test(application_error_list), cmocka_unit_test(check_macros),
        cmocka_unit_test(profile_sections),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
