using System;

namespace NavLink
{
    /// <summary>A failed nl_* call: its status and the calling thread's last error message, read right
    /// after the call (nl_get_last_error_message).</summary>
    public sealed class NavLinkException : Exception
    {
        public NavLinkException(uint status, string message)
            : base(string.IsNullOrEmpty(message) ? Status.Describe(status) : message)
        {
            StatusCode = status;
        }

        public NavLinkException(uint status, string message, Exception inner) : base(message, inner)
        {
            StatusCode = status;
        }

        public uint StatusCode { get; private set; }

        public bool Has(uint detailBit) { return (StatusCode & detailBit) != 0u; }
    }

    /// <summary>Turns statuses into exceptions.</summary>
    public static class Status
    {
        /// <summary>nl_status_string: "failure: invalid argument".</summary>
        public static string Describe(uint status) { return Utf8.Decode(Native.nl_status_string(status)); }

        /// <summary>The calling thread's last error message: call right after the failing function.</summary>
        public static string LastErrorMessage() { return Utf8.Decode(Native.nl_get_last_error_message()); }

        /// <summary>Throws NavLinkException if the status is a failure; returns it otherwise (it may
        /// carry PartialResult or be InProgress).</summary>
        public static uint Check(uint status)
        {
            if (StatusBits.Failed(status)) throw new NavLinkException(status, LastErrorMessage());
            return status;
        }
    }
}
