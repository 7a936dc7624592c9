using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public sealed partial class World
    {
        private unsafe delegate StatusCode ListFn(IntPtr buffer, uint capacity, uint* count);

        // The header's two-call pattern: ask the count, then fill a buffer of that size. The list can grow
        // between the two calls (another thread adds to it): BUFFER_TOO_SMALL then, and we ask again.
        // `first`: for lists of growable elements (Link...), their nl_*_init value, which the first element
        // takes so that the library knows this binding's element size.
        private static unsafe T[] ListTwoCall<T>(ListFn list, T? first = null) where T : struct
        {
            while (true)
            {
                uint count = 0;
                Status.Check(list(IntPtr.Zero, 0, &count));
                var items = new T[count];
                if (count == 0) return items;
                if (first.HasValue) items[0] = first.Value;
                GCHandle pin = GCHandle.Alloc(items, GCHandleType.Pinned);
                try
                {
                    StatusCode status = list(pin.AddrOfPinnedObject(), count, &count);
                    if (Status.IsBufferTooSmall(status)) continue;
                    Status.Check(status);
                }
                finally
                {
                    pin.Free();
                }
                if (count < items.Length) Array.Resize(ref items, (int)count);
                return items;
            }
        }
    }
}
