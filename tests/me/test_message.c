/* Messages: codes are unique and named, handlers receive code/level/function/text, counts, levels. */
#include "karma_test.h"

#include <string.h>

#include <karma/MeMemory.h>

static const struct {
    MeErrorCode code;
    int number;
} allCodes[] = {
#define ENTRY_(name, number, level, text) {name, number},
    ME_ERROR_LIST(ENTRY_)
#undef ENTRY_
};
enum { CODE_COUNT = sizeof allCodes / sizeof allCodes[0] };

static void codes_are_unique_and_named(void **state)
{
    (void)state;
    for (int i = 0; i < CODE_COUNT; i++) {
        assert_int_equal((int)allCodes[i].code, allCodes[i].number);
        assert_string_not_equal(MeErrorCodeName(allCodes[i].code), "unknown");
        assert_true(strncmp(MeErrorCodeName(allCodes[i].code), "ME_ERR_", 7) == 0);
        for (int j = i + 1; j < CODE_COUNT; j++)
            assert_int_not_equal(allCodes[i].number, allCodes[j].number);
    }
    assert_string_equal(MeErrorCodeName(ME_ERR_POOL_FULL), "ME_ERR_POOL_FULL");
    assert_string_equal(MeErrorCodeName((MeErrorCode)999), "unknown");
}

typedef struct Seen {
    int calls;
    MeMessageInfo last;
    char text[256];
} Seen;

static void remember(const MeMessageInfo *info, void *user)
{
    Seen *seen = user;
    seen->calls++;
    seen->last = *info;
    snprintf(seen->text, sizeof seen->text, "%s", info->text);
}

static void handler_receives_everything(void **state)
{
    (void)state;
    Seen seen = {0};
    void *previousUser = NULL;
    MeMessageHandler previous = MeSetMessageHandler(remember, &seen, &previousUser);
    MeSetMessageLevel(ME_LEVEL_INFO);
    MeMessageResetCounts();

    MeReport(ME_ERR_ARGUMENT_RANGE, "MdtTestFunction", "file.c", 12, "argument '%s' is %d", "n", -3);
    assert_int_equal(seen.calls, 1);
    assert_int_equal(seen.last.code, ME_ERR_ARGUMENT_RANGE);
    assert_int_equal(seen.last.level, ME_LEVEL_WARNING);
    assert_string_equal(seen.last.function, "MdtTestFunction");
    assert_int_equal(seen.last.line, 12);
    assert_string_equal(seen.text, "argument 'n' is -3");
    assert_int_equal(MeMessageGetCount(ME_ERR_ARGUMENT_RANGE), 1);
    assert_int_equal(MeMessageGetLastCode(), ME_ERR_ARGUMENT_RANGE);

    /* Below the level: counted, not delivered. */
    MeSetMessageLevel(ME_LEVEL_WARNING);
    MeReport(ME_ERR_CHUNK_GROWTH, "f", "file.c", 1, "grew");
    assert_int_equal(seen.calls, 1);
    assert_int_equal(MeMessageGetCount(ME_ERR_CHUNK_GROWTH), 1);
    assert_int_equal(MeMessageGetLastCode(), ME_ERR_ARGUMENT_RANGE); /* info does not replace it */

    /* Karma's printf-style calls arrive as user messages. */
    MeWarning(1, "value %d", 7);
    assert_int_equal(seen.calls, 2);
    assert_int_equal(seen.last.code, ME_ERR_USER_MESSAGE);
    assert_int_equal(seen.last.level, ME_LEVEL_WARNING);
    assert_string_equal(seen.text, "value 7");

    assert_int_equal(MeMessageGetTotalCount(ME_LEVEL_WARNING), 2);
    MeMessageResetCounts();
    assert_int_equal(MeMessageGetTotalCount(ME_LEVEL_DEBUG), 0);

    MeSetMessageHandler(previous, previousUser, NULL);
    MeSetMessageLevel(ME_LEVEL_INFO);
}

static void null_handler_restores_default(void **state)
{
    (void)state;
    MeSetMessageHandler(remember, NULL, NULL);
    MeMessageHandler was = MeSetMessageHandler(NULL, NULL, NULL);
    assert_ptr_equal(was, remember);
    void *user = (void *)1;
    assert_ptr_equal(MeSetMessageHandler(NULL, NULL, &user), MeDefaultMessageHandler);
    assert_null(user);
}

static void memory_api_counts_and_aligns(void **state)
{
    (void)state;
    MeMemoryStats before, after;
    MeMemoryGetStats(&before);
    void *a = MeMemoryCreate(100);
    void *b = MeMemoryCreateZeroed(64);
    void *c = MeMemoryCreateAligned(40, 64);
    assert_non_null(a);
    assert_non_null(b);
    assert_non_null(c);
    assert_int_equal((uintptr_t)c % 64, 0);
    for (int i = 0; i < 64; i++)
        assert_int_equal(((unsigned char *)b)[i], 0);
    a = MeMemoryResize(a, 1000);
    MeMemoryGetStats(&after);
    assert_int_equal(after.allocations - before.allocations, 4);
    assert_int_equal(after.liveBlocks - before.liveBlocks, 3);
    MeMemoryDestroy(a);
    MeMemoryDestroy(b);
    MeMemoryDestroyAligned(c);
    MeMemoryGetStats(&after);
    assert_int_equal(after.liveBlocks, before.liveBlocks);

    karma_capture_messages();
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(MeMemoryCreateAligned(16, 48)));
}

static int failingCalls;
static void *failingCreate(size_t n)
{
    (void)n;
    failingCalls++;
    return NULL;
}

static void replaced_allocator_is_used(void **state)
{
    (void)state;
    MeMemoryAPIStruct api = *MeMemoryGetDefaultAPI();
    api.create = failingCreate;
    MeMemorySetAPI(&api);
    karma_capture_messages();
    assert_reports(ME_ERR_OUT_OF_MEMORY, assert_null(MeMemoryCreate(10)));
    assert_int_equal(failingCalls, 1);
    MeMemorySetAPI(NULL);
    void *p = MeMemoryCreate(10);
    assert_non_null(p);
    MeMemoryDestroy(p);
    /* An incomplete table is refused. */
    api.destroy = NULL;
    assert_reports(ME_ERR_NULL_ARGUMENT, MeMemorySetAPI(&api));
    assert_ptr_equal(MeMemoryGetAPI()->create, MeMemoryGetDefaultAPI()->create);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(codes_are_unique_and_named),
        cmocka_unit_test(handler_receives_everything),
        cmocka_unit_test(null_handler_restores_default),
        cmocka_unit_test(memory_api_counts_and_aligns),
        cmocka_unit_test(replaced_allocator_is_used),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
