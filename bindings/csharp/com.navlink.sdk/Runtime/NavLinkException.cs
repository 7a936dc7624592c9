using System;

namespace NavLink
{
    /// <summary>A failed nl_* call: its status and the calling thread's last error message, read right
    /// after the call (nl_get_last_error_message). Also thrown when libnavlink cannot be loaded (status
    /// Failure | NotFound, the message says where the library is looked for).</summary>
    public sealed class NavLinkException : Exception
    {
        public NavLinkException(StatusCode status, string message)
            : base(string.IsNullOrEmpty(message) ? Status.Describe(status) : message)
        {
            StatusCode = status;
        }

        public NavLinkException(StatusCode status, string message, Exception inner) : base(message, inner)
        {
            StatusCode = status;
        }

        /// <summary>Failure and the detail bits: StatusCode.Failure | StatusCode.InvalidHandle.</summary>
        public StatusCode StatusCode { get; private set; }

        /// <summary>Whether the status carries this detail (StatusCode.InvalidHandle...).</summary>
        public bool Has(StatusCode detail) { return Status.Has(StatusCode, detail); }
    }

    /// <summary>Reads statuses, and turns failed ones into exceptions.</summary>
    public static class Status
    {
        public static bool Succeeded(StatusCode status) { return (status & StatusCode.Success) != 0; }

        public static bool Failed(StatusCode status) { return (status & StatusCode.Failure) != 0; }

        /// <summary>Whether status has every bit of detail.</summary>
        public static bool Has(StatusCode status, StatusCode detail) { return detail != 0 && (status & detail) == detail; }

        /// <summary>nl_status_string: "failure: invalid argument".</summary>
        public static string Describe(StatusCode status) { return Utf8.Decode(Native.nl_status_string(status)); }

        /// <summary>The calling thread's last error message: call right after the failing function.</summary>
        public static string LastErrorMessage() { return Utf8.Decode(Native.nl_get_last_error_message()); }

        /// <summary>Throws NavLinkException if the status is a failure; returns it otherwise (it may
        /// carry PartialResult or be InProgress).</summary>
        public static StatusCode Check(StatusCode status)
        {
            if (Failed(status)) throw new NavLinkException(status, LastErrorMessage());
            return status;
        }

        /// <summary>A failure with this detail: the loop of the two-call pattern asks again on it.</summary>
        internal static bool IsBufferTooSmall(StatusCode status)
        {
            return Failed(status) && Has(status, StatusCode.BufferTooSmall);
        }
    }
}
