/* Test scaffolding for Wine 8 only: Rust's standard library (1.78 and
 * later) imports ProcessPrng from bcryptprimitives.dll, which Windows 10
 * and later have and Wine 8 lacks. This stand-in fills the buffer from
 * RtlGenRandom (advapi32's SystemFunction036). Never shipped beside
 * opengl32.dll. */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T len)
{
    while (len > 0) {
        ULONG n = len > 0x10000000 ? 0x10000000 : (ULONG)len;
        if (!SystemFunction036(data, n))
            return FALSE;
        data += n;
        len -= n;
    }
    return TRUE;
}
